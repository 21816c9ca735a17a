// Seed 002 part B: the MAKLINK free-space graph and the ant colony system over offsets along its
// free lines (acs_maklink). Collision checks here use the world's exact obstacle distances, not
// the polygons the planner builds.
#include <gtest/gtest.h>

#include <cmath>

#include "core/input_error.h"
#include "planning/planner_registry.h"
#include "planning/swarm/acs_maklink.h"
#include "planning/swarm/maklink_graph.h"

using namespace cosim;

namespace {

Obstacle box(double x, double y, double sx, double sy, double yaw = 0.0) {
  Obstacle o;
  o.type = ObstacleType::Box;
  o.pos = {x, y, 2.0};
  o.size = {sx, sy, 4.0};
  o.yaw_deg = yaw;
  return o;
}

Obstacle cylinder(double x, double y, double r) {
  Obstacle o;
  o.type = ObstacleType::Cylinder;
  o.pos = {x, y, 2.0};
  o.radius = r;
  o.height = 4.0;
  return o;
}

// A 20 m x 20 m room with two offset walls, a rotated box and a pillar.
World room() {
  World w;
  w.bounds_min = {0, 0, 0};
  w.bounds_max = {20, 20, 5};
  w.obstacles = {box(6, 7, 1.5, 14), box(13, 13, 1.5, 14), box(16, 5, 3, 2, 30),
                 cylinder(9.5, 15, 1.2)};
  return w;
}

PlanningProblem problem(const World& w, Eigen::Vector3d start, Eigen::Vector3d goal) {
  PlanningProblem p;
  p.world = &w;
  p.start = start;
  p.goal = goal;
  p.inflation = 0.4;
  p.seed = 1;
  return p;
}

// Samples every segment 5 mm apart: each sample keeps the inflation's clearance from every
// obstacle and stays inside the bounds shrunk by the inflation.
void expectCollisionFree(const World& w, const Path& path, double inflation) {
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const Eigen::Vector3d a = path.waypoints[i], b = path.waypoints[i + 1];
    const int n = 1 + static_cast<int>((b - a).norm() / 0.005);
    for (int k = 0; k <= n; ++k) {
      const Eigen::Vector3d p = a + (b - a) * (static_cast<double>(k) / n);
      ASSERT_GE(w.distanceToObstacles(p), inflation - 1e-6) << "segment " << i << " at " << k;
      ASSERT_TRUE(w.insideBounds(p, inflation - 1e-6)) << "segment " << i;
    }
  }
}

MaklinkGraph roomGraph(const World& w, double inflation) {
  return MaklinkGraph(planarObstacles(w, 1.0, inflation, 8), Eigen::Vector2d(inflation, inflation),
                      Eigen::Vector2d(20 - inflation, 20 - inflation));
}

}  // namespace

TEST(MaklinkGraph, FreeLinesAvoidObstaclesNeverCrossAndEndOnVerticesOrWalls) {
  const World w = room();
  const MaklinkGraph g = roomGraph(w, 0.4);
  ASSERT_GT(g.lines().size(), 10u);
  for (std::size_t i = 0; i < g.lines().size(); ++i) {
    const MaklinkLine& l = g.lines()[i];
    EXPECT_TRUE(g.segmentFree(l.a, l.b)) << i;
    for (std::size_t j = i + 1; j < g.lines().size(); ++j)
      EXPECT_FALSE(segmentsCrossProperly(l.a, l.b, g.lines()[j].a, g.lines()[j].b))
          << i << "," << j;
    for (const Eigen::Vector2d& end : {l.a, l.b}) {
      bool on_vertex = false;
      for (const ConvexPolygon& p : g.obstacles())
        for (const Eigen::Vector2d& v : p.vertices) on_vertex |= (v - end).norm() < 1e-9;
      const bool on_wall = std::fabs(end.x() - 0.4) < 1e-9 || std::fabs(end.x() - 19.6) < 1e-9 ||
                           std::fabs(end.y() - 0.4) < 1e-9 || std::fabs(end.y() - 19.6) < 1e-9;
      EXPECT_TRUE(on_vertex || on_wall) << "line " << i;
    }
  }
}

TEST(MaklinkGraph, AnyOffsetsOnConsecutiveCrossedLinesSeeEachOther) {
  // The regions between free lines are convex, so every pair of offsets on two consecutive
  // lines of the route is joined by a free segment (what lets the ants choose offsets freely).
  const World w = room();
  const MaklinkGraph g = roomGraph(w, 0.4);
  const MaklinkRoute r = g.shortestRoute({1, 1}, {19, 19});
  ASSERT_TRUE(r.found);
  ASSERT_GE(r.lines.size(), 2u);
  for (std::size_t i = 0; i + 1 < r.lines.size(); ++i)
    for (int a = 0; a <= 10; ++a)
      for (int b = 0; b <= 10; ++b)
        EXPECT_TRUE(g.segmentFree(g.lines()[r.lines[i]].at(a / 10.0),
                                  g.lines()[r.lines[i + 1]].at(b / 10.0)))
            << "lines " << i << "," << i + 1 << " offsets " << a << "," << b;
}

TEST(AcsMaklink, ShortensDijkstrasMidpointPathAndStaysClear) {
  const World w = room();
  AcsMaklink planner;
  const PlanningProblem p = problem(w, {1, 1, 1}, {19, 19, 1});
  const PlanResult r = planner.solve(p, StopToken::untimed());
  ASSERT_TRUE(r.success) << r.message;
  expectCollisionFree(w, r.path, p.inflation);
  EXPECT_LT(r.path.length(), r.counters.at("dijkstra_length_m") * 0.95);
  EXPECT_EQ(r.path.waypoints.front(), p.start);
  EXPECT_EQ(r.path.waypoints.back(), p.goal);
  // Both walls force the path to zigzag: it is longer than the straight 25.46 m.
  EXPECT_GT(r.path.length(), 25.5);
  EXPECT_EQ(r.path.size(), r.counters.at("crossed_lines") + 2);
}

TEST(AcsMaklink, OffsetsAreOnTheLevelsAndFinerLevelsAreNoWorseAtBest) {
  const World w = room();
  const MaklinkGraph g = roomGraph(w, 0.4);
  double best11 = 1e9, best21 = 1e9;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    AcsMaklinkParams p11, p21;
    p21.levels = 21;
    const AcsMaklinkResult r11 = optimiseMaklinkRoute(g, {1, 1}, {19, 19}, p11, seed, StopToken(5));
    const AcsMaklinkResult r21 = optimiseMaklinkRoute(g, {1, 1}, {19, 19}, p21, seed, StopToken(5));
    ASSERT_TRUE(r11.success && r21.success);
    for (double h : r11.offsets) EXPECT_NEAR(h * 10, std::round(h * 10), 1e-9);
    EXPECT_LE(r11.length, r11.dijkstra_length + 1e-9);
    EXPECT_LE(r11.iterations, 200);
    best11 = std::min(best11, r11.length);
    best21 = std::min(best21, r21.length);
  }
  EXPECT_LE(best21, best11 + 1e-9);
}

TEST(AcsMaklink, SameSeedSamePath) {
  const World w = room();
  AcsMaklink a, b;
  const PlanningProblem p = problem(w, {1, 1, 1}, {19, 19, 1});
  const PlanResult r1 = a.solve(p, StopToken::untimed()), r2 = b.solve(p, StopToken::untimed());
  ASSERT_TRUE(r1.success);
  EXPECT_EQ(r1.path.waypoints, r2.path.waypoints);
}

TEST(AcsMaklink, EnclosedGoalAndGoalInsideObstacleAreReported) {
  World w;
  w.bounds_min = {0, 0, 0};
  w.bounds_max = {20, 20, 5};
  w.obstacles = {box(10, 7, 8, 1), box(10, 13, 8, 1), box(6.5, 10, 1, 7), box(13.5, 10, 1, 7)};
  AcsMaklink planner;
  const PlanResult enclosed =
      planner.solve(problem(w, {1, 1, 1}, {10, 10, 1}), StopToken::untimed());
  EXPECT_FALSE(enclosed.success);
  EXPECT_NE(enclosed.message.find("unreachable"), std::string::npos) << enclosed.message;
  const PlanResult inside = planner.solve(problem(w, {1, 1, 1}, {10, 7, 1}), StopToken::untimed());
  EXPECT_FALSE(inside.success);
  EXPECT_NE(inside.message.find("goal"), std::string::npos) << inside.message;
}

TEST(AcsMaklink, PlansAtStartHeightAndClimbsToTheGoal) {
  World w = room();
  Obstacle low = box(3, 16, 2, 2);  // 0..1 m high: not in the plane at z = 2
  low.pos.z() = 0.5;
  low.size.z() = 1.0;
  w.obstacles.push_back(low);
  AcsMaklink planner;
  const PlanningProblem p = problem(w, {1, 1, 2}, {19, 19, 3});
  const PlanResult r = planner.solve(p, StopToken::untimed());
  ASSERT_TRUE(r.success) << r.message;
  for (std::size_t i = 0; i + 1 < r.path.size(); ++i) EXPECT_DOUBLE_EQ(r.path.waypoints[i].z(), 2);
  EXPECT_EQ(r.path.waypoints.back(), p.goal);
  expectCollisionFree(w, r.path, p.inflation);
}

TEST(AcsMaklink, RegisteredWithTheSeedsParameterNames) {
  ParamSet params("s.yaml");
  params.set("q0", "0.9");
  params.set("beta", "2");
  params.set("rho", "0.1");
  params.set("tau0", "0.0002");
  params.set("ants", "10");
  params.set("iterations", "50");
  params.set("levels", "21");
  auto planner = makePlanner("acs_maklink", params);
  EXPECT_EQ(planner->name(), "acs_maklink");
  ParamSet bad("s.yaml");
  bad.set("q0", "1.5");
  EXPECT_THROW(makePlanner("acs_maklink", bad), InputError);
}

TEST(AcsMaklink, TimeLimitIsHonouredWhileBuildingALargeGraph) {
  World w;
  w.bounds_min = {0, 0, 0};
  w.bounds_max = {100, 100, 5};
  for (int i = 0; i < 15; ++i)
    for (int j = 0; j < 15; ++j) w.obstacles.push_back(cylinder(5 + 6.3 * i, 5 + 6.3 * j, 1.0));
  AcsMaklink planner;
  PlanningProblem p = problem(w, {1, 1, 1}, {99, 99, 1});
  p.time_limit_s = 0.05;  // 225 octagons: 1800 vertices, far more than 50 ms of candidate lines
  const PlanResult r = planner.solve(p, StopToken::untimed());
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("time limit"), std::string::npos) << r.message;
  EXPECT_LT(r.time_ms, 500.0);
}
