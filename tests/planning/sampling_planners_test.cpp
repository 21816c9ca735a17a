// The sampling planners (prm, rrt, rrt_star, rrt_star_thesis, rrt_star_fn, rrt_connect,
// informed_rrt_star):
// paths checked independently of CollisionWorld (dense sampling with World::distanceToObstacles),
// determinism, convergence of RRT* to a known optimum, and failures reported, not hung.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/input_error.h"
#include "planning/planner_registry.h"

namespace cosim {
namespace {

const std::vector<std::string> kPlanners = {
    "prm", "rrt", "rrt_star", "rrt_star_thesis", "rrt_star_fn", "rrt_connect", "informed_rrt_star"};

std::unique_ptr<Planner> make(const std::string& name,
                              const std::map<std::string, std::string>& params = {}) {
  ParamSet p("test");
  for (const auto& [k, v] : params) p.set(k, v);
  return makePlanner(name, p);
}

// 30 x 30 x 10 world with boxes, cylinders and spheres between start and goal.
World clutteredWorld() {
  World w;
  w.bounds_min = {0, 0, 0};
  w.bounds_max = {30, 30, 10};
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 40; ++i) {
    Obstacle o;
    o.type = static_cast<ObstacleType>(i % 3);
    o.pos = {5 + 20 * u(rng), 5 + 20 * u(rng), 10 * u(rng)};
    o.size = {1 + 3 * u(rng), 1 + 3 * u(rng), 2 + 6 * u(rng)};
    o.radius = 0.5 + 1.5 * u(rng);
    o.height = 10;
    o.yaw_deg = 90 * u(rng);
    w.obstacles.push_back(o);
  }
  return w;
}

// From corner to corner of clutteredWorld(), for a vehicle of radius + margin 0.3 m.
PlanningProblem acrossClutter(const World& w) {
  PlanningProblem prob;
  prob.world = &w;
  prob.start = {1, 1, 1};
  prob.goal = {29, 29, 8};
  prob.inflation = 0.3;
  return prob;
}

// Independent check: every point of the path, sampled every 5 mm, is inside the bounds and
// farther than the inflation from every obstacle (up to 1e-9 m).
void expectPathValid(const PlanningProblem& prob, const PlanResult& r) {
  ASSERT_TRUE(r.success) << r.message;
  ASSERT_GE(r.path.size(), 2u);
  EXPECT_EQ(r.path.waypoints.front(), prob.start);
  EXPECT_EQ(r.path.waypoints.back(), prob.goal);
  for (std::size_t i = 1; i < r.path.size(); ++i) {
    const Eigen::Vector3d a = r.path.waypoints[i - 1], b = r.path.waypoints[i];
    const int n = static_cast<int>((b - a).norm() / 0.005) + 1;
    for (int k = 0; k <= n; ++k) {
      const Eigen::Vector3d p = a + (b - a) * (static_cast<double>(k) / n);
      ASSERT_TRUE(prob.world->insideBounds(p));
      ASSERT_GE(prob.world->distanceToObstacles(p), prob.inflation - 1e-9)
          << "segment " << i << " at " << p.transpose();
    }
  }
}

TEST(SamplingPlanners, EveryPlannerReturnsCollisionFreePathInsideBounds) {
  const World w = clutteredWorld();
  PlanningProblem prob = acrossClutter(w);
  for (const auto& name : kPlanners) {
    for (std::uint64_t seed : {1, 2}) {
      prob.seed = seed;
      SCOPED_TRACE(name + " seed " + std::to_string(seed));
      const PlanResult r = make(name, {{"max_nodes", "5000"}})->solve(prob, StopToken::untimed());
      expectPathValid(prob, r);
      EXPECT_GE(r.path.length(), (prob.goal - prob.start).norm());
      EXPECT_GT(r.counters.at("collision_checks"), 0);
      EXPECT_GT(r.counters.at("nodes"), 2);
    }
  }
}

// With a node budget every planner is deterministic for a seed (without one the anytime planners
// stop at a time limit, so their paths depend on the machine's speed, as OMPL's).
TEST(SamplingPlanners, SameSeedGivesSamePathAndAnotherSeedAnother) {
  const World w = clutteredWorld();
  PlanningProblem prob = acrossClutter(w);
  for (const auto& name : kPlanners) {
    SCOPED_TRACE(name);
    const std::map<std::string, std::string> budget = {{"max_nodes", "2000"}};
    prob.seed = 5;
    const PlanResult a = make(name, budget)->solve(prob, StopToken::untimed());
    const PlanResult b = make(name, budget)->solve(prob, StopToken::untimed());
    prob.seed = 6;
    const PlanResult c = make(name, budget)->solve(prob, StopToken::untimed());
    ASSERT_TRUE(a.success && b.success && c.success);
    EXPECT_EQ(a.path.waypoints, b.path.waypoints);
    EXPECT_EQ(a.counters, b.counters);
    EXPECT_NE(a.path.waypoints, c.path.waypoints);
  }
}

// Planar world: the box [9, 11] x [3, 7] between start (2, 5) and goal (18, 5), inflated by 0.5:
// the shortest path runs tangent to the rounded corner circles (centres (9, 7) and (11, 7),
// radius 0.5), around them and along the top face at y = 7.5.
double optimumAroundBox() {
  const Eigen::Vector2d s(2, 5), c(9, 7);
  const double r = 0.5, d = (s - c).norm();
  const double tangent = std::sqrt(d * d - r * r);
  // Direction from the centre to the tangent point, then the arc up to the top point (0, 1).
  // (s - c) points down-left (angle in (pi, 3 pi / 2)); the upper tangent point is acos(r / d)
  // back towards the top.
  const double from_centre = std::atan2(s.y() - c.y(), s.x() - c.x()) + 2 * M_PI - std::acos(r / d);
  const double arc = r * (from_centre - M_PI / 2);
  return 2 * (tangent + arc) + 2.0;
}

TEST(SamplingPlanners, RrtStarCostDecreasesWithBudgetTowardsTheKnownOptimum) {
  World w;
  w.bounds_min = {0, 0, 0};
  w.bounds_max = {20, 10, 2};
  Obstacle box;
  box.pos = {10, 5, 1};
  box.size = {2, 4, 4};
  w.obstacles.push_back(box);
  PlanningProblem prob;
  prob.world = &w;
  prob.start = {2, 5, 1};
  prob.goal = {18, 5, 1};
  prob.inflation = 0.5;
  prob.planar = true;
  const double optimum = optimumAroundBox();
  // Sanity of the formula: 2 (sqrt(52.75) + 0.5 * 0.3472) + 2.
  ASSERT_NEAR(optimum, 16.873, 0.001);
  double previous = 1e9;
  for (const char* budget : {"300", "1500", "6000"}) {
    double mean = 0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      prob.seed = seed;
      const PlanResult r =
          make("rrt_star",
               {{"max_nodes", budget}, {"mode", "2"}, {"step", "1"}, {"rewire_radius", "1.5"}})
              ->solve(prob, StopToken::untimed());
      ASSERT_TRUE(r.success) << budget;
      // No planner may beat the true optimum: that would mean cutting the rounded corners.
      EXPECT_GE(r.path.length(), optimum - 1e-9);
      mean += r.path.length() / 3;
    }
    EXPECT_LT(mean, previous) << "budget " << budget;
    previous = mean;
  }
  EXPECT_LT(previous, optimum * 1.005);  // measured: 0.16 % above
}

TEST(SamplingPlanners, StartOrGoalBlockedOrOutOfBoundsIsReportedAsFailure) {
  const World w = clutteredWorld();
  PlanningProblem prob;
  prob.world = &w;
  prob.inflation = 0.3;
  const Eigen::Vector3d inside = w.obstacles[0].pos;
  struct Case {
    Eigen::Vector3d start, goal;
    std::string message;
  };
  const std::vector<Case> cases = {{inside, {29, 29, 8}, "start ("},
                                   {{1, 1, 1}, inside, "goal ("},
                                   {{1, 1, 1}, {29, 29, 11}, "outside the world bounds"},
                                   {{-1, 1, 1}, {29, 29, 8}, "outside the world bounds"}};
  for (const auto& name : kPlanners) {
    for (const Case& c : cases) {
      prob.start = c.start;
      prob.goal = c.goal;
      const PlanResult r = make(name)->solve(prob, StopToken::untimed());
      EXPECT_FALSE(r.success) << name;
      EXPECT_NE(r.message.find(c.message), std::string::npos) << name << ": " << r.message;
    }
  }
  prob.start = inside;
  prob.goal = {29, 29, 8};
  EXPECT_NE(make("rrt")->solve(prob, StopToken::untimed()).message.find("inside an obstacle"),
            std::string::npos);
}

TEST(SamplingPlanners, EnclosedGoalEndsWithTimeLimitNotAHang) {
  // The goal sits in a closed room of six walls.
  World w;
  w.bounds_min = {0, 0, 0};
  w.bounds_max = {20, 20, 10};
  const Eigen::Vector3d c(15, 15, 5);
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0}) {
      Obstacle wall;
      wall.pos = c;
      wall.pos[axis] += side * 2.0;
      wall.size = {4.4, 4.4, 4.4};
      wall.size[axis] = 0.4;
      w.obstacles.push_back(wall);
    }
  PlanningProblem prob;
  prob.world = &w;
  prob.start = {2, 2, 2};
  prob.goal = c;
  prob.inflation = 0.2;
  prob.time_limit_s = 0.1;
  for (const auto& name : kPlanners) {
    const PlanResult r = make(name)->solve(prob, StopToken::untimed());
    EXPECT_FALSE(r.success) << name;
    EXPECT_EQ(r.message.rfind("time limit (0.1 s) reached after ", 0), 0u)
        << name << ": " << r.message;
    EXPECT_LT(r.time_ms, 2000.0) << name;  // generous: the limit is 100 ms
  }
  // With a small node budget the failure is the budget, not the clock.
  prob.time_limit_s = 10;
  const PlanResult r =
      make("rrt", {{"max_nodes", "500"}, {"mode", "2"}})->solve(prob, StopToken::untimed());
  EXPECT_EQ(r.message.rfind("no path within max_nodes = 500 (obstacles inflated by 0.2 m", 0), 0u)
      << r.message;
  EXPECT_EQ(r.counters.at("nodes"), 500);
}

TEST(SamplingPlanners, FixedNodesCapBoundsTheTreeAndModesUseTheBudget) {
  const World w = clutteredWorld();
  PlanningProblem prob = acrossClutter(w);
  const PlanResult fn =
      make("rrt_star_fn", {{"max_tree_nodes", "300"}, {"mode", "2"}, {"max_nodes", "2000"}})
          ->solve(prob, StopToken::untimed());
  ASSERT_TRUE(fn.success);
  EXPECT_EQ(fn.counters.at("nodes"), 2000);  // seed 003's N, set
  EXPECT_LE(fn.counters.at("tree_nodes"), 301);
  EXPECT_GE(fn.counters.at("removed_nodes"), 1600);
  EXPECT_GT(fn.counters.at("rewires"), 0);
  const PlanResult mode1 = make("rrt", {{"max_nodes", "2000"}})->solve(prob, StopToken::untimed());
  const PlanResult mode2 =
      make("rrt", {{"mode", "2"}, {"max_nodes", "2000"}})->solve(prob, StopToken::untimed());
  EXPECT_LT(mode1.counters.at("nodes"), 2000);
  EXPECT_EQ(mode2.counters.at("nodes"), 2000);
  EXPECT_EQ(mode1.path.waypoints, mode2.path.waypoints);  // RRT never improves its path
}

TEST(SamplingPlanners, PlanarProblemsStayInTheStartPlane) {
  const World w = clutteredWorld();
  PlanningProblem prob;
  prob.world = &w;
  prob.start = {1, 1, 0.5};
  prob.goal = {29, 29, 0.5};
  prob.inflation = 0.3;
  prob.planar = true;
  for (const auto& name : kPlanners) {
    const PlanResult r = make(name, {{"time_limit", "0.1"}})->solve(prob, StopToken::untimed());
    ASSERT_TRUE(r.success) << name;
    for (const auto& p : r.path.waypoints) EXPECT_EQ(p.z(), 0.5) << name;
  }
}

TEST(SamplingPlanners, ShortcuttingShortensAndKeepsThePathFree) {
  const World w = clutteredWorld();
  PlanningProblem prob = acrossClutter(w);
  for (const auto& name : kPlanners) {
    SCOPED_TRACE(name);
    const PlanResult plain = make(name, {{"max_nodes", "2000"}})->solve(prob, StopToken::untimed());
    const PlanResult cut = make(name, {{"shortcut", "true"}, {"max_nodes", "2000"}})
                               ->solve(prob, StopToken::untimed());
    expectPathValid(prob, cut);
    EXPECT_LE(cut.path.length(), plain.path.length() + 1e-9);
    EXPECT_LT(cut.path.size(), plain.path.size());
  }
}

TEST(SamplingPlanners, ParametersOfOtherPlannersAreIgnoredButMisspellingsAndBadValuesRejected) {
  // rewire_radius belongs to rrt_star: for rrt it is collected as ignored where the caller asks
  // for that (plan-bench), an error otherwise; a name no planner takes is an error either way.
  ParamSet p("test");
  p.set("rewire_radius", "3");
  std::vector<std::string> ignored;
  EXPECT_NO_THROW(makePlanner("rrt", p, "key planner.name", &ignored));
  ASSERT_EQ(ignored.size(), 1u);
  EXPECT_EQ(ignored[0], "rewire_radius");
  EXPECT_THROW(make("rrt", {{"rewire_radius", "3"}}), InputError);
  EXPECT_THROW(make("rrt", {{"rewire_radiuss", "3"}}), InputError);
  EXPECT_THROW(make("rrt_star_fn", {{"mode", "3"}}), InputError);
  EXPECT_NO_THROW(make("prm", {{"k", "15"}, {"step", "4"}}));
}

}  // namespace
}  // namespace cosim
