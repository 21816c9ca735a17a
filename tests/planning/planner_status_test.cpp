// Every planner says how its search ended with a PlannerStatus, not only in words: a solution is
// ExactSolution, a blocked start InvalidStart, and a search ended by a stop request (SIGINT or
// SIGTERM in the program, core/stop_request.h) Stopped, never Timeout, so that the command line
// can tell an interrupt from a failure.
#include "planning/planner_status.h"

#include <gtest/gtest.h>

#include <set>

#include "core/stop_request.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/planner_registry.h"
#include "planning/trajectory/minimum_snap_trajectory.h"
#include "planning/trajectory/segment_time_allocation.h"

using namespace cosim;

namespace {

// A 12 m x 12 m room, 2 m high, with one box in the middle; start and goal at one height, as
// the planners that plan on the start's layer need.
World roomWithABox() {
  World w;
  w.bounds_min = {0, 0, 0};
  w.bounds_max = {12, 12, 2};
  Obstacle box;
  box.pos = {6, 6, 1};
  box.size = {2, 2, 2};
  w.obstacles.push_back(box);
  return w;
}

PlanResult plan(const std::string& name, const Eigen::Vector3d& start, double time_limit_s) {
  const World world = roomWithABox();
  ParamSet params("test");
  auto planner = makePlanner(name, params);
  PlanningProblem problem;
  problem.world = &world;
  problem.start = start;
  problem.goal = {10, 10, 1};
  problem.inflation = 0.2;
  problem.planar = true;
  problem.time_limit_s = time_limit_s;
  return planner->solve(problem, StopToken::untimed());
}

std::vector<std::string> singleAgentPlanners() {
  std::vector<std::string> names;
  for (const auto& e : PlannerRegistry::instance().entries()) names.push_back(e.name);
  return names;
}

std::vector<std::string> teamPlanners() {
  std::vector<std::string> names;
  for (const auto& e : mapfPlanners()) names.push_back(e.name);
  return names;
}

class EverySingleAgentPlanner : public ::testing::TestWithParam<std::string> {};

TEST_P(EverySingleAgentPlanner, ASolutionIsAnExactSolution) {
  const PlanResult r = plan(GetParam(), {2, 2, 1}, 10.0);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ(toString(r.status), "exact_solution");
}

TEST_P(EverySingleAgentPlanner, AStartInsideTheBoxIsAnInvalidStart) {
  const PlanResult r = plan(GetParam(), {6, 6, 1}, 10.0);
  EXPECT_FALSE(r.success);
  EXPECT_EQ(toString(r.status), "invalid_start") << r.message;
}

TEST_P(EverySingleAgentPlanner, AStopRequestEndsTheSearchAsStoppedWithAnHourToGo) {
  requestStop();
  const PlanResult r = plan(GetParam(), {2, 2, 1}, 3600.0);
  clearStopRequest();
  EXPECT_EQ(toString(r.status), "stopped") << r.message;
  EXPECT_LT(r.time_ms, 2000.0);
}

INSTANTIATE_TEST_SUITE_P(Registry, EverySingleAgentPlanner,
                         ::testing::ValuesIn(singleAgentPlanners()));

// Two agents on an open 8 x 8 map whose shortest paths never meet: every team planner, the
// uncoordinated baseline too, solves it.
MapfInstance twoApart() {
  MapfInstance inst;
  inst.grid = OccupancyGrid(8, 8);
  inst.starts = {{0, 0, 0}, {0, 7, 0}};
  inst.goals = {{7, 0, 0}, {7, 7, 0}};
  return inst;
}

MapfResult solveTeam(const std::string& name, const std::atomic<bool>* stop) {
  const MapfInstance inst = twoApart();
  ParamSet params("test");
  MapfQuery query;
  query.instance = &inst;
  query.time_limit_s = 3600.0;
  return makeMapfPlanner(name, params)->solve(query, StopToken::untimed(stop));
}

class EveryTeamPlanner : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryTeamPlanner, ASolutionIsAnExactSolution) {
  const MapfResult r = solveTeam(GetParam(), nullptr);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ(toString(r.status), "exact_solution");
}

TEST_P(EveryTeamPlanner, TheCallersStopFlagEndsTheSearchAsStopped) {
  const std::atomic<bool> stop{true};
  const MapfResult r = solveTeam(GetParam(), &stop);
  EXPECT_EQ(toString(r.status), "stopped") << r.message;
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryTeamPlanner, ::testing::ValuesIn(teamPlanners()));

// The trajectory optimisation honours the stop request too: NLopt is stopped (force_stop) at its
// first cost evaluation, and the fit ends as Stopped instead of running its repair rounds.
TEST(MinimumSnapStop, AStopRequestStopsNloptAndTheFit) {
  Path zigzag;
  for (int i = 0; i < 12; ++i) zigzag.waypoints.push_back({2.0 * i, (i % 2) * 3.0, 1.0});
  const MinimumSnapTrajectory generator;
  const MinimumSnapResult free_fit = generator.fit(zigzag);
  ASSERT_TRUE(free_fit.success);
  EXPECT_EQ(free_fit.status, PlannerStatus::ExactSolution);
  EXPECT_GT(free_fit.counters.at("cost_evaluations"), 1.0);

  std::vector<Eigen::Vector3d> points = zigzag.waypoints;
  const MinimumSnapClosedForm closed_form(points);
  const std::vector<double> initial = distanceProportionalTimes(closed_form, 100.0);
  const std::atomic<bool> stop{true};
  const StopToken token(1e9, &stop);
  const TimeAllocationResult allocation =
      optimizeSegmentTimes(closed_form, initial, 100.0, 400, &token);
  EXPECT_TRUE(allocation.stopped);
  EXPECT_EQ(allocation.evaluations, 0);
  EXPECT_EQ(allocation.durations, initial);

  requestStop();
  const MinimumSnapResult stopped = generator.fit(zigzag);
  clearStopRequest();
  EXPECT_FALSE(stopped.success);
  EXPECT_EQ(stopped.status, PlannerStatus::Stopped);
  EXPECT_EQ(stopped.counters.at("cost_evaluations"), 0.0);
}

TEST(PlannerStatus, EveryValueHasItsOwnName) {
  std::set<std::string> names;
  for (int s = static_cast<int>(PlannerStatus::Unknown);
       s <= static_cast<int>(PlannerStatus::InvalidSolution); ++s)
    names.insert(toString(static_cast<PlannerStatus>(s)));
  EXPECT_EQ(names.size(), 11u);
  EXPECT_EQ(names.count("unknown"), 1u);
  EXPECT_EQ(names.count("limit_reached"), 1u);
}

TEST(PlannerStatus, AnExpiredTokenIsATimeoutUnlessAStopWasRequested) {
  const StopToken expired(0.0);
  EXPECT_EQ(expiredStatus(expired), PlannerStatus::Timeout);
  EXPECT_EQ(searchStatus(true, expired, PlannerStatus::NoSolution), PlannerStatus::ExactSolution);
  EXPECT_EQ(searchStatus(false, StopToken(60.0), PlannerStatus::LimitReached),
            PlannerStatus::LimitReached);
  const std::atomic<bool> stop{true};
  const StopToken stopped(60.0, &stop);
  EXPECT_EQ(expiredStatus(stopped), PlannerStatus::Stopped);
  EXPECT_EQ(searchStatus(true, stopped, PlannerStatus::NoSolution), PlannerStatus::Stopped);
}

}  // namespace
