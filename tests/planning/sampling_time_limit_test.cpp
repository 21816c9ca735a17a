// Sampling planners that do not give up early: without max_nodes they run until their
// time limit, non-anytime planners return their first path, anytime planners (the RRT*s) keep
// improving for their `time_limit`, and max_nodes still stops them when it is set (the thesis
// modes of the reproductions).
#include <gtest/gtest.h>

#include "planning/planner_registry.h"
#include "tests/planning/narrow_window_world.h"
#include "tests/planning/path_clearance_check.h"

namespace cosim {
namespace {

std::unique_ptr<Planner> make(const std::string& name,
                              const std::map<std::string, std::string>& params = {}) {
  ParamSet p("test");
  for (const auto& [k, v] : params) p.set(k, v);
  return makePlanner(name, p);
}

double counter(const PlanResult& r, const char* name) {
  return r.counters.count(name) ? r.counters.at(name) : 0.0;
}

// The acceptance case: with defaults RRT-Connect crosses the 1.2 m window for 10 of 10 seeds
// (with the old 2000-node cap it did for 3), and every path is clear by an independent check.
TEST(SamplingTimeLimit, RrtConnectWithDefaultsCrossesNarrowWindowForEverySeed) {
  const World w = narrowWindowWorld();
  for (const double inflation : {0.385}) {  // quad_1500g's radius, margin 0: 3/10 with the cap
    PlanningProblem prob = throughNarrowWindow(w, inflation);
    prob.time_limit_s = 10.0;
    auto planner = make("rrt_connect");
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      prob.seed = seed;
      const PlanResult r = planner->solve(prob, StopToken::untimed());
      ASSERT_TRUE(r.success) << "inflation " << inflation << " seed " << seed << ": " << r.message;
      EXPECT_EQ(r.path.waypoints.front(), prob.start);
      EXPECT_EQ(r.path.waypoints.back(), prob.goal);
      EXPECT_GE(smallestPathClearance(w, r.path), inflation - 1e-9) << "seed " << seed;
    }
  }
}

TEST(SamplingTimeLimit, PrmWithDefaultsCrossesNarrowWindow) {
  const World w = narrowWindowWorld();
  PlanningProblem prob = throughNarrowWindow(w, 0.3);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    prob.seed = seed;
    const PlanResult r = make("prm")->solve(prob, StopToken::untimed());
    ASSERT_TRUE(r.success) << "seed " << seed << ": " << r.message;
    EXPECT_GE(smallestPathClearance(w, r.path), 0.3 - 1e-9);
  }
}

// A node budget that is set still stops the search, and the message says so.
TEST(SamplingTimeLimit, MaxNodesStopsOnlyWhenSet) {
  const World w = narrowWindowWorld();
  const PlanningProblem prob = throughNarrowWindow(w, 0.45);
  const PlanResult capped =
      make("rrt_connect", {{"max_nodes", "20"}})->solve(prob, StopToken::untimed());
  EXPECT_FALSE(capped.success);
  EXPECT_EQ(counter(capped, "nodes"), 20);
  EXPECT_NE(capped.message.find("no path within max_nodes = 20"), std::string::npos)
      << capped.message;
  EXPECT_NE(capped.message.find("inflated by 0.45 m"), std::string::npos) << capped.message;
}

// Anytime: rrt_star keeps improving for its time_limit; a longer limit gives more nodes and a
// path no longer than the first one found; mode 1 (the thesis's) stops at the first path.
TEST(SamplingTimeLimit, RrtStarImprovesUntilItsTimeLimitAndModeOneStopsAtFirstPath) {
  const World w = narrowWindowWorld();
  PlanningProblem prob = throughNarrowWindow(w, 0.3);
  prob.seed = 4;
  const PlanResult first = make("rrt_star", {{"mode", "1"}})->solve(prob, StopToken::untimed());
  const PlanResult brief =
      make("rrt_star", {{"time_limit", "0.05"}})->solve(prob, StopToken::untimed());
  const PlanResult longer =
      make("rrt_star", {{"time_limit", "0.3"}})->solve(prob, StopToken::untimed());
  ASSERT_TRUE(first.success && brief.success && longer.success);
  EXPECT_EQ(counter(first, "nodes"), counter(first, "first_path_nodes"));
  EXPECT_EQ(counter(longer, "stopped_by_time_limit"), 1);
  EXPECT_GE(longer.time_ms, 300.0);
  EXPECT_LT(longer.time_ms, 1500.0);
  EXPECT_GT(counter(longer, "nodes"), counter(brief, "nodes"));
  EXPECT_LT(longer.path.length(), first.path.length());
  // The straight lines through the window's centre give (nearly) the shortest path.
  const Eigen::Vector3d window = narrowWindowCentre();
  const double bound = (window - prob.start).norm() + (prob.goal - window).norm();
  EXPECT_GE(longer.path.length(), bound - 0.6);
  EXPECT_GE(smallestPathClearance(w, longer.path), 0.3 - 1e-9);
}

// The anytime default is 1 s of improvement: the run must stay quick. The search for a first
// path is not cut at 1 s, only by the problem's own limit.
TEST(SamplingTimeLimit, AnytimeDefaultImprovesForOneSecondAndHonoursTheProblemLimit) {
  const World w = narrowWindowWorld(4.0);  // a wide window: a first path comes at once
  PlanningProblem prob = throughNarrowWindow(w, 0.3);
  prob.time_limit_s = 0.2;
  const PlanResult r = make("informed_rrt_star")->solve(prob, StopToken::untimed());
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_LT(r.time_ms, 600.0);  // the problem's 0.2 s, not the planner's 1 s
  ParamSet p("test");
  auto planner = makePlanner("rrt_star", p);
  EXPECT_EQ(p.effective().at("time_limit"), "1");
  EXPECT_EQ(p.effective().at("max_nodes"), "0");
  EXPECT_EQ(p.effective().at("mode"), "2");
}

// The thesis's mode 2 with its node budget N: the whole budget is used, not the time limit.
TEST(SamplingTimeLimit, ThesisModeTwoUsesTheNodeBudgetNotTheClock) {
  const World w = narrowWindowWorld();
  const PlanningProblem prob = throughNarrowWindow(w, 0.3);
  const PlanResult r = make("rrt_star_thesis", {{"mode", "2"}, {"max_nodes", "1500"}})
                           ->solve(prob, StopToken::untimed());
  EXPECT_EQ(counter(r, "nodes"), 1500);
}

}  // namespace
}  // namespace cosim
