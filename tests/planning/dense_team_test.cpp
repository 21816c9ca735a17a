// Dense quadrotor teams: conflicts by the separation ellipsoids (vertex, edge, swept) worked by
// hand, the reservations of the prioritised search, the roadmap chosen from the starts and goals,
// and a small dense team planned and smoothed with every pair apart by an independent check.
#include <gtest/gtest.h>

#include <cmath>

#include "core/input_error.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/team/dense_roadmap.h"
#include "planning/team/dense_team_search.h"
#include "planning/team/ellipsoid_conflict.h"
#include "planning/team/ellipsoid_reservations.h"
#include "planning/team/quadrotor_team_planner.h"

using namespace cosim;
using Eigen::Vector3d;

namespace {

const SeparationEllipsoid kCf2{0.24, 0.6};

double swept(const Vector3d& a0, const Vector3d& a1, const Vector3d& b0, const Vector3d& b1) {
  return sweptEllipsoidDistance(kCf2, a0, a1, b0, b1);
}

World room(double x, double y) {
  World w;
  w.bounds_min = {0, 0, 0};
  w.bounds_max = {x, y, 2.5};
  return w;
}

// Eight cf2 in two 2 x 2 blocks at 0.5 m, each bound for the mirror image of its start.
std::vector<TeamAgent> denseSwap() {
  std::vector<TeamAgent> agents;
  for (const double x : {0.8, 1.3})
    for (const double y : {1.25, 1.75})
      for (const double side : {0.0, 1.0}) {
        TeamAgent a;
        a.start = {side > 0 ? 5 - x : x, y, 1};
        a.goal = {side > 0 ? x : 5 - x, y, 1};
        a.separation = kCf2;
        a.inflation = 0.17;
        a.clearance = 0.12;
        agents.push_back(a);
      }
  return agents;
}

}  // namespace

TEST(EllipsoidConflict, StandingPairsAreTheirEllipsoidalDistanceApart) {
  // 0.3 m side by side: 0.3 / 0.24 = 1.25; 0.45 m one above the other: 0.45 / 0.6 = 0.75.
  const Vector3d a(1, 1, 1);
  EXPECT_NEAR(swept(a, a, a + Vector3d(0.3, 0, 0), a + Vector3d(0.3, 0, 0)), 1.25, 1e-12);
  EXPECT_NEAR(swept(a, a, a + Vector3d(0, 0, 0.45), a + Vector3d(0, 0, 0.45)), 0.75, 1e-12);
}

TEST(EllipsoidConflict, EdgeConflictsSwapAndRightAngleFollowing) {
  const Vector3d o(0, 0, 1), x(0.36, 0, 0), y(0, 0.36, 0);
  // A swap meets in the middle.
  EXPECT_NEAR(swept(o, o + x, o + x, o), 0.0, 1e-12);
  // Entering what the other leaves at a right angle: relative (-1.5, 0) to (0, -1.5) in scaled
  // units, closest halfway, 1.5 / sqrt(2).
  EXPECT_NEAR(swept(o, o + x, o + x, o + x + y), 1.5 / std::sqrt(2.0), 1e-12);
  // Following straight on keeps the spacing.
  EXPECT_NEAR(swept(o, o + x, o + x, o + 2 * x), 1.5, 1e-12);
}

TEST(EllipsoidConflict, TheSweptCheckCatchesMovesThatPassCloserThanAtEitherEnd) {
  // Two moves 0.12 m apart sideways, passing each other: 1.58 at both ends, 0.5 halfway.
  const Vector3d o(0, 0, 1), x(0.36, 0, 0), side(0, 0.12, 0);
  EXPECT_NEAR(swept(o, o, o + x + side, o + x + side), std::hypot(1.5, 0.5), 1e-12);
  EXPECT_NEAR(swept(o, o + x, o + x + side, o + side), 0.5, 1e-12);
}

TEST(EllipsoidReservations, AReservedPathBlocksTheMovesAndTheGoalsItComesCloseTo) {
  // Eight vertices on a line 0.18 m apart; separation 1.4 ellipsoids (0.336 m side by side).
  std::vector<Vector3d> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(0.18 * i, 0, 1);
  EllipsoidReservations r(p, kCf2, 1.4, Vector3d(0.18, 0.18, 0.45));
  r.reserve({0, 1, 2});  // moves right for two steps, rests at vertex 2 (0.36 m) from step 2
  EXPECT_EQ(r.staticFrom(), 2);
  EXPECT_FALSE(r.moveConflicts(3, 3, 0));   // 0.54 m while it goes 0 -> 0.18: 2.25 to 1.5
  EXPECT_TRUE(r.moveConflicts(2, 2, 1));    // it arrives where another stands
  EXPECT_TRUE(r.moveConflicts(4, 3, 2));    // towards the resting one: 1.5 down to 0.75
  EXPECT_TRUE(r.moveConflicts(3, 3, 50));   // beside the resting one (0.75) long after
  EXPECT_FALSE(r.moveConflicts(4, 4, 50));  // 1.5 from it
  EXPECT_EQ(r.lastConflictStanding(4), -1);
  EXPECT_EQ(r.lastConflictStanding(3), EllipsoidReservations::kForever);
  r.clear();
  r.reserve({6, 6, 6, 0});  // waits at 1.08 m, then one move to 0 across vertex 3 at step 2
  EXPECT_EQ(r.staticFrom(), 3);
  EXPECT_EQ(r.lastConflictStanding(3), 2);
  EXPECT_FALSE(r.moveConflicts(3, 3, 1));
  EXPECT_TRUE(r.moveConflicts(3, 3, 2));
}

TEST(DenseRoadmap, StartsHalfAMetreApartLandOnDistinctVerticesOfTheCoarsestLattice) {
  const World w = room(5, 3);
  std::vector<Vector3d> starts, goals;
  for (const auto& a : denseSwap()) {
    starts.push_back(a.start);
    goals.push_back(a.goal);
  }
  const DenseRoadmap r = denseRoadmap(w, starts, goals, kCf2, 1.5, 0.17);
  EXPECT_EQ(r.refinement, 1);  // 0.36 m x 0.9 m: one separation per lattice step
  EXPECT_NEAR(r.grid.pitch().x(), 1.5 * 0.24, 1e-5);
  for (std::size_t j = 0; j < starts.size(); ++j)
    for (std::size_t i = 0; i < j; ++i)
      EXPECT_GE(kCf2.distance(r.positions[r.starts[i]], r.positions[r.starts[j]]), 1.5);
  // All at z = 1: only that layer is open.
  for (int v = 0; v < r.graph.vertexCount(); ++v) EXPECT_NEAR(r.positions[v].z(), 1.0, 1e-9);
}

TEST(DenseRoadmap, StartsCloserThanTheSeparationAreBadInputNamingTheLaterVehicle) {
  const World w = room(5, 3);
  try {
    denseRoadmap(w, {{1, 1, 1}, {1.3, 1, 1}}, {{3, 1, 1}, {3, 2, 1}}, kCf2, 1.5, 0.17);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "vehicles[1].start");  // 0.3 m: 1.25 ellipsoids
  }
}

TEST(DenseTeamSearch, EightCf2SwappingHalfAMetreApartKeepTheSeparationAtEveryInstant) {
  const World w = room(5, 3);
  const auto agents = denseSwap();
  std::vector<Vector3d> starts, goals;
  for (const auto& a : agents) {
    starts.push_back(a.start);
    goals.push_back(a.goal);
  }
  const DenseRoadmap r = denseRoadmap(w, starts, goals, kCf2, 1.5, 0.17);
  DenseTeamQuery q;
  q.graph = &r.graph;
  q.positions = &r.positions;
  q.pitch = r.grid.pitch();
  q.ellipsoid = kCf2;
  q.separation = 1.5;
  q.starts = r.starts;
  q.goals = r.goals;
  const DenseTeamResult d = planDenseTeam(q);
  ASSERT_TRUE(d.success) << d.message;
  // Independent of the closed form: every move sampled at 20 points.
  double closest = 1e9;
  const std::size_t steps = d.paths.front().size();
  for (std::size_t t = 0; t + 1 < steps; ++t)
    for (int k = 0; k <= 20; ++k) {
      const double u = k / 20.0;
      for (std::size_t i = 0; i < agents.size(); ++i)
        for (std::size_t j = i + 1; j < agents.size(); ++j) {
          const auto at = [&](std::size_t a) {
            return ((1 - u) * r.positions[d.paths[a][t]] + u * r.positions[d.paths[a][t + 1]])
                .eval();
          };
          closest = std::min(closest, kCf2.distance(at(i), at(j)));
        }
    }
  EXPECT_GE(closest, 1.5 - 1e-9);
  EXPECT_LT(closest, 2.0);  // they did pass close
  for (std::size_t a = 0; a < agents.size(); ++a) EXPECT_EQ(d.paths[a].back(), r.goals[a]);
  EXPECT_GE(closestLockStepDistance(d.paths, r.positions, kCf2), 1.5);
}

TEST(QuadrotorTeamPlanner, ADenseTeamTheGridCannotHoldIsPlannedOnTheRoadmapAndSmoothedApart) {
  const World w = room(5, 3);
  TeamPlanningProblem p;
  p.world = &w;
  p.agents = denseSwap();
  ParamSet params;
  auto lacam = makeMapfPlanner("lacam", params);
  const TeamPlan r = planQuadrotorTeam(p, *lacam);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ(r.counters.at("dense_roadmap_refinement"), 1);
  double end = 0.0;
  for (const auto& t : r.trajectories) end = std::max(end, t.duration());
  double closest = 1e9, highest = 0, lowest = 1e9;
  for (double t = 0; t <= end; t += 0.005)
    for (std::size_t i = 0; i < p.agents.size(); ++i) {
      const Vector3d a = r.trajectories[i].sample(t).position;
      highest = std::max(highest, a.z());
      lowest = std::min(lowest, a.z());
      for (std::size_t j = i + 1; j < p.agents.size(); ++j)
        closest = std::min(closest, kCf2.distance(a, r.trajectories[j].sample(t).position));
    }
  EXPECT_GE(closest, 0.98 * p.min_separation);
  EXPECT_NEAR(highest, 1.0, 1e-6);  // planar: nobody flies in another's downwash
  EXPECT_NEAR(lowest, 1.0, 1e-6);
  for (std::size_t i = 0; i < p.agents.size(); ++i)
    EXPECT_LT((r.trajectories[i].sample(end).position - p.agents[i].goal).norm(), 1e-6);
}
