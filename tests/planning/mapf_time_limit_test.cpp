// Every MAPF planner honours its time limit and the process's stop request at every stage,
// including the per-agent set-up that used to run unchecked (CBS with 20 000 agents: a 5 s limit
// took 37.8 s), and instances whose tables would need more than about 1 GB (each planner's own
// measure) are refused before anything is allocated.
#include <gtest/gtest.h>

#include "core/stop_token.h"
#include "core/input_error.h"
#include "planning/mapf/goal_distance_table.h"
#include "planning/mapf/mapf_graph.h"
#include "planning/mapf/mapf_grid.h"
#include "planning/mapf/mapf_memory_estimate.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/mapf/maze_generator.h"
#include "planning/mapf/reverse_resumable_astar.h"
#include "core/stop_request.h"

using namespace cosim;

namespace {

// `agents` agents on an open 64 x 64 map: starts along the top rows, goals along the bottom.
MapfInstance openInstance(int agents) {
  MapfInstance inst;
  inst.grid = OccupancyGrid(64, 64);
  for (int i = 0; i < agents; ++i) {
    inst.starts.push_back({i % 64, i / 64, 0});
    inst.goals.push_back({63 - i % 64, 63 - i / 64, 0});
  }
  return inst;
}

MapfResult solve(const std::string& planner, const MapfInstance& inst, double time_limit_s) {
  ParamSet p("test");
  MapfQuery q;
  q.instance = &inst;
  q.time_limit_s = time_limit_s;
  return makeMapfPlanner(planner, p)->solve(q, StopToken::untimed());
}

class EveryHeuristicPlanner : public ::testing::TestWithParam<std::string> {};

// A limit that has passed before the planner starts: it stops in its set-up, without one search.
TEST_P(EveryHeuristicPlanner, StopsBeforeAnySearchWhenItsTimeIsUp) {
  const MapfInstance inst = openInstance(400);
  const MapfResult r = solve(GetParam(), inst, 1e-12);
  EXPECT_FALSE(r.success);
  EXPECT_EQ(r.message, "time limit reached");
  const auto expansions = r.counters.find("expansions");
  EXPECT_TRUE(expansions == r.counters.end() || expansions->second == 0.0);
}

// SIGINT/SIGTERM (requestStop) reach the planner through its deadline: with an hour to go, it
// still stops at once.
TEST_P(EveryHeuristicPlanner, AStopRequestEndsItAtOnce) {
  const MapfInstance inst = openInstance(400);
  requestStop();
  const MapfResult r = solve(GetParam(), inst, 3600.0);
  clearStopRequest();
  EXPECT_FALSE(r.success);
  EXPECT_EQ(r.message, "time limit reached");
}

INSTANTIATE_TEST_SUITE_P(Planners, EveryHeuristicPlanner,
                         ::testing::Values("cbs", "hca_star", "whca_star"));

TEST(ReverseResumableAStar, PastItsDeadlineAnUnexpandedCellGetsTheAdmissibleLowerBound) {
  OccupancyGrid g(256, 256);
  for (int y = 0; y < 255; ++y) g.setBlocked(128, y, 0, true);  // a wall with a gap at the bottom
  const MapfGrid grid(g, 4);
  const int goal = grid.id({0, 0, 0}), far = grid.id({255, 0, 0});
  const StopToken expired(0.0);
  ReverseResumableAStar late(grid, goal, far, &expired);
  // The true distance goes around the wall (255 + 2 * 255 = 765); the bound is 255.
  EXPECT_EQ(late.distance(far), grid.lowerBound(far, goal));
  EXPECT_LT(late.expansions(), 1100);  // stopped at its first deadline check
  ReverseResumableAStar exact(grid, goal, far);
  EXPECT_EQ(exact.distance(far), 765);
}

// The guard measures each planner's own tables: 30 agents on an open 2000 x 2000 map need 30
// full Reverse Resumable A* tables for hca_star (30 x 4e6 x 5 bytes = 572 MB: accepted), 60 of
// them are refused (1144 MB); lacam's lazy distance tables cover free cells once per distinct
// goal in 16 bits when the distances fit (2000 x 2000 open: diameter about 4000), so 1000
// agents there need 1000 x 4e6 x 2 bytes = 7629 MB (refused) and 100 agents 763 MB (accepted).
TEST(MapfInstanceLimits, EachPlannersTablesAreEstimatedAndBeyondAGigabyteRefused) {
  MapfInstance inst;
  inst.grid = OccupancyGrid(2000, 2000);
  const auto agents = [&](int n) {
    inst.starts.clear();
    inst.goals.clear();
    for (int i = 0; i < n; ++i) {
      inst.starts.push_back({i % 2000, i / 2000, 0});
      inst.goals.push_back({i % 2000, 1999 - i / 2000, 0});
    }
  };
  agents(30);
  EXPECT_NO_THROW(checkMapfTableMemory(inst, "hca_star", "x.scen"));
  EXPECT_NEAR(estimateMapfTableMemory(inst, "hca_star").bytes, 30 * 4e6 * 5, 1.0);
  agents(60);
  try {
    checkMapfTableMemory(inst, "hca_star", "x.scen");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "agents");
    EXPECT_NE(e.problem().find("1144 MB (60 agents x 4000000 cells x 5 bytes)"),
              std::string::npos)
        << e.problem();
  }
  agents(100);
  EXPECT_NO_THROW(checkMapfTableMemory(inst, "lacam", "x.scen"));
  EXPECT_NEAR(estimateMapfTableMemory(inst, "lacam").bytes, 100 * 4e6 * 2, 1.0);
  agents(1000);
  EXPECT_THROW(checkMapfTableMemory(inst, "pibt", "x.scen"), InputError);
}

// Agents with the same goal share one row of lazy distances; the row is written only as far
// as the searches went (a 1 x 1000 corridor, goal at 0: asking for cell 10 reaches 11 cells).
TEST(MapfInstanceLimits, LazyDistanceTablesShareRowsAndCountOnlyWhatWasSearched) {
  OccupancyGrid corridor(1000, 1);
  const MapfGraph graph = MapfGraph::fromGrid(corridor, 4);
  const std::vector<int> goals = {0, 0, 999};
  const GoalDistanceTable table(graph, goals);
  EXPECT_EQ(table.rowCount(), 2);
  EXPECT_EQ(table(0, 10), 10u);
  EXPECT_EQ(table(1, 10), 10u);  // the same row: no second search
  EXPECT_EQ(table(2, 990), 9u);
  // Entries reached: 11 + 10 (2 bytes each); frontiers: two rings of 16 ints.
  EXPECT_EQ(table.bytesReached(), 21u * 2 + 2 * 16 * sizeof(int));
  EXPECT_EQ(table.bytes(), 2u * 1000 * 2 + 2 * 16 * sizeof(int));
}

TEST(MapfInstanceLimits, AMapLargerThanMultiAgentPlanningAllowsIsRefused) {
  MapfInstance inst;
  inst.grid = OccupancyGrid(5000, 5000);
  inst.starts.push_back({0, 0, 0});
  inst.goals.push_back({1, 0, 0});
  EXPECT_THROW(checkMapfInstance(inst, "x.scen"), InputError);
}

}  // namespace
