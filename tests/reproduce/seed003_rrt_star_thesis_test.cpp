// Seed 003's own RRT* (its Fig. 16 choose-parent, planner rrt_star_thesis) beside Karaman and
// Frazzoli's (rrt_star) on seed 003's maps, and the linear-scan nearest-neighbour search that
// reproduces the thesis's cost structure without changing any answer.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "core/input_error.h"
#include "experiments/reproduce/seed003_maps.h"
#include "planning/planner_registry.h"

namespace cosim {
namespace {

PlanResult plan(const std::string& planner, const Seed003Map& map, std::uint64_t seed,
                const std::map<std::string, std::string>& params) {
  ParamSet p("test");
  for (const auto& [k, v] : params) p.set(k, v);
  PlanningProblem prob;
  prob.world = &map.world;
  prob.start = map.start;
  prob.goal = map.goal;
  prob.planar = map.planar;
  prob.seed = seed;
  prob.time_limit_s = 30.0;
  return makePlanner(planner, p)->solve(prob, StopToken::untimed());
}

// The thesis's Tab. 16 settings: map 3, mode 2, N 2000, step 2 m, radius 4 m, no goal bias.
const std::map<std::string, std::string> kSet3 = {{"mode", "2"},
                                                  {"max_nodes", "2000"},
                                                  {"step", "2"},
                                                  {"rewire_radius", "4"},
                                                  {"goal_bias", "0"}};

TEST(RrtStarThesis, OneCandidateParentLeavesLongerPathsThanKaramanFrazzoliOnMap3) {
  const Seed003Map map = seed003Maps()[3];
  ASSERT_EQ(map.name, "3d-3");
  double thesis = 0.0, kf = 0.0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const PlanResult a = plan("rrt_star_thesis", map, seed, kSet3);
    const PlanResult b = plan("rrt_star", map, seed, kSet3);
    ASSERT_TRUE(a.success && b.success);
    // The same samples, steered from the same nearest nodes: the trees hold the same points.
    EXPECT_EQ(a.counters.at("first_path_nodes"), b.counters.at("first_path_nodes"));
    thesis += a.path.length();
    kf += b.path.length();
  }
  // Measured over 100 runs: 86.3 m against 82.1 m (seed003-sampling, Tab. 16).
  EXPECT_GT(thesis, 1.02 * kf);
}

TEST(RrtStarThesis, CapsItsTreeAsRrtStarFnAndIsRrtStarWithTheThesissParentRule) {
  const Seed003Map map = seed003Maps()[2];  // map 2
  const PlanResult capped =
      plan("rrt_star_thesis", map, 3,
           {{"mode", "2"}, {"max_nodes", "2000"}, {"max_tree_nodes", "400"}, {"step", "2"}});
  ASSERT_TRUE(capped.success);
  EXPECT_EQ(capped.counters.at("nodes"), 2000);
  EXPECT_LE(capped.counters.at("tree_nodes"), 401);
  EXPECT_GE(capped.counters.at("removed_nodes"), 1500);
  EXPECT_THROW(plan("rrt_star", map, 1, {{"choose_parent", "nearest"}}), InputError);
  // choose_parent nearest_parent makes rrt_star the thesis's RRT*: the very same path (in the
  // thesis's mode 1, rrt_star_thesis's default; rrt_star is anytime by default).
  const PlanResult a = plan("rrt_star_thesis", map, 4, {{"goal_bias", "0"}});
  const PlanResult b = plan(
      "rrt_star", map, 4, {{"goal_bias", "0"}, {"choose_parent", "nearest_parent"}, {"mode", "1"}});
  ASSERT_TRUE(a.success && b.success);
  EXPECT_EQ(a.path.waypoints, b.path.waypoints);
}

TEST(RrtStarThesis, LinearScanChangesTheCostNotTheTree) {
  const Seed003Map map = seed003Maps()[1];
  for (const char* planner : {"rrt", "rrt_star_thesis", "rrt_star_fn"}) {
    SCOPED_TRACE(planner);
    std::map<std::string, std::string> p = {{"mode", "2"}, {"max_nodes", "800"}};
    const PlanResult kd = plan(planner, map, 9, p);
    p["neighbour_search"] = "linear";
    const PlanResult scan = plan(planner, map, 9, p);
    ASSERT_TRUE(kd.success && scan.success);
    EXPECT_EQ(kd.path.waypoints, scan.path.waypoints);
    EXPECT_EQ(kd.counters.at("nodes"), scan.counters.at("nodes"));
  }
}

// The thesis's two candidate causes of its mode 2 barely shortening the path (Tabs. 4-5). With
// both, the goal keeps the cost it got at the first path: the same as mode 1's on the same seed
// (the runs are identical up to that path), though the path itself still shortens through its
// rewired ancestors. With neither (the usual RRT*), mode 2 lowers the goal's cost to the length.
TEST(RrtStarThesis, WithoutCostPassingOrGoalReattachingTheGoalKeepsItsFirstCost) {
  const Seed003Map map = seed003Maps()[0];
  ASSERT_EQ(map.name, "2d");
  const std::map<std::string, std::string> both = {{"rewire_costs", "node"},
                                                   {"goal_reattach", "false"}};
  auto settings = [](const char* mode, std::map<std::string, std::string> extra) {
    extra.insert({{"mode", mode}, {"max_nodes", "1000"}, {"step", "1"}, {"rewire_radius", "3"}});
    return extra;
  };
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const PlanResult m1 = plan("rrt_star_thesis", map, seed, settings("1", both));
    const PlanResult m2 = plan("rrt_star_thesis", map, seed, settings("2", both));
    ASSERT_TRUE(m1.success && m2.success);
    EXPECT_DOUBLE_EQ(m2.counters.at("goal_cost"), m1.counters.at("goal_cost"));
    EXPECT_LT(m2.path.length(), m2.counters.at("goal_cost") - 1e-9);  // the stale value
    const PlanResult usual = plan("rrt_star_thesis", map, seed, settings("2", {}));
    ASSERT_TRUE(usual.success);
    EXPECT_NEAR(usual.counters.at("goal_cost"), usual.path.length(), 1e-6);
    EXPECT_LT(usual.counters.at("goal_cost"), m1.counters.at("goal_cost"));
  }
}

TEST(RrtStarThesis, RejectsAnUnknownRewireCostRule) {
  ParamSet p("test");
  p.set("rewire_costs", "ancestors");
  EXPECT_THROW(makePlanner("rrt_star_thesis", p), InputError);
}

}  // namespace
}  // namespace cosim
