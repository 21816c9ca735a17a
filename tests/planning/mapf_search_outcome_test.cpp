// How a multi-agent search ends, as a value: Conflict-Based Search's typed outcome (solved, an
// unreachable goal with the agent named, the constraint-tree node limit) and the words and
// PlannerStatus the planner derives from it; and every MAPF planner's solve() ending when its
// caller's StopToken expires, even with a long time limit of its own.
#include <gtest/gtest.h>

#include "mapf_test_instances.h"
#include "planning/mapf/cbs_search.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/mapf/mapf_search_context.h"

using namespace cosim;

namespace {

CbsOutcome searchCbs(const MapfInstance& inst, const ConflictBasedSearchOptions& options) {
  MapfQuery query;
  query.instance = &inst;
  query.time_limit_s = 60.0;
  MapfSearchContext context(query, StopToken::untimed());
  std::vector<int> starts, goals;
  for (int a = 0; a < inst.agentCount(); ++a) {
    starts.push_back(context.start(a));
    goals.push_back(context.goal(a));
  }
  CbsSearch search(context.grid(), starts, goals,
                   context.goalDistances(MapfSearchContext::Heuristic::kTrueDistance), options,
                   context.deadline());
  return search.run();
}

MapfResult solveWith(const std::string& planner, const MapfInstance& inst,
                     const std::vector<std::pair<std::string, std::string>>& params,
                     const StopToken& stop) {
  ParamSet p("test");
  for (const auto& [k, v] : params) p.set(k, v);
  MapfQuery query;
  query.instance = &inst;
  query.time_limit_s = 3600.0;
  return makeMapfPlanner(planner, p)->solve(query, stop);
}

// Agent 1's goal lies behind a wall.
MapfInstance walledOffGoal() {
  return test::instanceFrom({"...@."}, {{0, 0, 0}, {1, 0, 0}}, {{2, 0, 0}, {4, 0, 0}});
}

}  // namespace

TEST(CbsSearch, SolvesThePocketCorridorAtTheOptimalSumOfCosts) {
  const CbsOutcome out = searchCbs(test::pocketCorridor(), {});
  ASSERT_EQ(out.status, CbsOutcome::Status::kSolved);
  ASSERT_EQ(out.paths.size(), 2u);
  // 5 + 7 steps: agent 0 ducks into the pocket (mapf_test_instances.h).
  EXPECT_EQ(out.paths[0].size() - 1 + out.paths[1].size() - 1, 12u);
  EXPECT_GE(out.low_level_calls, 3);  // two root paths and at least one replan
}

TEST(CbsSearch, NamesTheAgentWhoseGoalIsUnreachable) {
  const CbsOutcome out = searchCbs(walledOffGoal(), {});
  EXPECT_EQ(out.status, CbsOutcome::Status::kUnreachable);
  EXPECT_EQ(out.agent, 1);
  const MapfResult r = solveWith("cbs", walledOffGoal(), {}, StopToken::untimed());
  EXPECT_EQ(r.status, PlannerStatus::NoSolution);
  EXPECT_EQ(r.message, "goal of agent 1 is unreachable");
}

TEST(CbsSearch, StopsAtTheConstraintTreeNodeLimit) {
  ConflictBasedSearchOptions options;
  options.max_nodes = 2;  // the root's first split would make three nodes
  const CbsOutcome out = searchCbs(test::pocketCorridor(), options);
  EXPECT_EQ(out.status, CbsOutcome::Status::kNodeLimit);
  EXPECT_EQ(out.ct_nodes, 1);
  const MapfResult r =
      solveWith("cbs", test::pocketCorridor(), {{"max_nodes", "2"}}, StopToken::untimed());
  EXPECT_EQ(r.status, PlannerStatus::LimitReached);
  EXPECT_EQ(r.message, "constraint-tree node limit (max_nodes) reached");
  EXPECT_FALSE(r.success);
}

TEST(MapfSearchContext, EveryPlannerEndsWhenItsCallersTokenHasExpired) {
  // Two agents crossing an empty room on rows of their own: every planner solves it.
  const MapfInstance inst = test::instanceFrom({"....", "....", "....", "...."},
                                               {{0, 0, 0}, {0, 3, 0}}, {{3, 0, 0}, {3, 3, 0}});
  const StopToken expired(0.0);  // the caller's own deadline, already past
  for (const MapfPlannerEntry& entry : mapfPlanners()) {
    // (independent_astar polls its clock only every so many expansions: on a map this small its
    // searches end first, as they do past an expired time limit of the query's own.)
    if (entry.name != "independent_astar") {
      const MapfResult r = solveWith(entry.name, inst, {}, expired);
      EXPECT_FALSE(r.success) << entry.name;
      EXPECT_EQ(r.status, PlannerStatus::Timeout) << entry.name << ": " << r.message;
    }
    // The same planner with a live token solves it, within the query's own time limit.
    EXPECT_TRUE(solveWith(entry.name, inst, {}, StopToken::untimed()).success) << entry.name;
  }
}
