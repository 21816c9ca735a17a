// Every MAPF planner honours its time limit and the process's stop request at every stage,
// including the per-agent set-up that used to run unchecked (CBS with 20 000 agents: a 5 s limit
// took 37.8 s), and instances too large for the planners' per-agent tables are refused before
// anything is allocated.
#include <gtest/gtest.h>

#include "core/stop_token.h"
#include "core/input_error.h"
#include "planning/mapf/mapf_grid.h"
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
  return makeMapfPlanner(planner, p)->solve(q);
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

TEST(MapfInstanceLimits, AgentsTimesCellsBeyondThePlannersTablesIsRefusedBeforePlanning) {
  MapfInstance inst;
  inst.grid = OccupancyGrid(2000, 2000);
  for (int i = 0; i < 30; ++i) {
    inst.starts.push_back({i, 0, 0});
    inst.goals.push_back({i, 1999, 0});
  }
  try {
    checkMapfInstance(inst, "x.scen");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "agents");
    EXPECT_NE(e.problem().find("30 agents x 4000000 cells = 120000000"), std::string::npos)
        << e.problem();
  }
  inst.starts.resize(25);  // 1e8: at the limit, accepted
  inst.goals.resize(25);
  EXPECT_NO_THROW(checkMapfInstance(inst, "x.scen"));
}

TEST(MapfInstanceLimits, AMapLargerThanMultiAgentPlanningAllowsIsRefused) {
  MapfInstance inst;
  inst.grid = OccupancyGrid(5000, 5000);
  inst.starts.push_back({0, 0, 0});
  inst.goals.push_back({1, 0, 0});
  EXPECT_THROW(checkMapfInstance(inst, "x.scen"), InputError);
}

}  // namespace
