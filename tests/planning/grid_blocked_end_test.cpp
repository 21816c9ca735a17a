// A grid planner's blocked start or goal: the status says which end (InvalidStart or
// InvalidGoal) and the message names it, from the one PathEnd the check ran on.
#include <gtest/gtest.h>

#include "core/param_set.h"
#include "core/stop_token.h"
#include "planning/grid/grid_passage_diagnosis.h"
#include "planning/planner_registry.h"

namespace cosim {
namespace {

// A 12 m x 12 m room with a 2 m box in the middle; `goal` may be inside it.
PlanResult planTo(const Eigen::Vector3d& start, const Eigen::Vector3d& goal) {
  World world;
  world.bounds_min = {0, 0, 0};
  world.bounds_max = {12, 12, 2};
  Obstacle box;
  box.pos = {6, 6, 1};
  box.size = {2, 2, 2};
  world.obstacles.push_back(box);
  ParamSet params("test");
  auto planner = makePlanner("astar", params);
  PlanningProblem problem;
  problem.world = &world;
  problem.start = start;
  problem.goal = goal;
  problem.inflation = 0.2;
  problem.planar = true;
  problem.time_limit_s = 10.0;
  return planner->solve(problem, StopToken::untimed());
}

TEST(GridBlockedEnd, AGoalInsideTheBoxIsAnInvalidGoalNamedGoal) {
  const PlanResult r = planTo({2, 2, 1}, {6, 6, 1});
  EXPECT_EQ(r.status, PlannerStatus::InvalidGoal);
  EXPECT_EQ(r.message.rfind("goal cell is blocked at resolution 0.5 m", 0), 0u) << r.message;
}

TEST(GridBlockedEnd, AStartInsideTheBoxIsAnInvalidStartNamedStart) {
  const PlanResult r = planTo({6, 6, 1}, {10, 10, 1});
  EXPECT_EQ(r.status, PlannerStatus::InvalidStart);
  EXPECT_EQ(r.message.rfind("start cell is blocked at resolution 0.5 m", 0), 0u) << r.message;
}

TEST(GridBlockedEnd, NamesOfTheEndsAndBlockingModes) {
  EXPECT_STREQ(pathEndName(PathEnd::Start), "start");
  EXPECT_STREQ(pathEndName(PathEnd::Goal), "goal");
  EXPECT_STREQ(blockingName(OccupancyGrid::Blocking::AnyPoint), "cell");
  EXPECT_STREQ(blockingName(OccupancyGrid::Blocking::Exact), "exact");
  EXPECT_STREQ(blockingName(OccupancyGrid::Blocking::Centre), "centre");
}

}  // namespace
}  // namespace cosim
