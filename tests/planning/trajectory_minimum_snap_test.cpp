#include <gtest/gtest.h>

#include <cmath>

#include "core/input_error.h"
#include "planning/trajectory/inflated_world.h"
#include "planning/trajectory/minimum_snap_closed_form.h"
#include "planning/trajectory/minimum_snap_trajectory.h"
#include "planning/trajectory/segment_time_allocation.h"
#include "planning/trajectory/waypoint_thinning.h"

using namespace cosim;
using Eigen::Vector3d;

namespace {

// Sum of x, y, z snap costs approximated by Simpson's rule on a fine grid.
double numericSnapCost(const PiecewisePolynomialTrajectory& traj) {
  double cost = 0.0;
  for (std::size_t i = 0; i < traj.pieces().size(); ++i) {
    const double T = traj.pieces()[i].duration;
    const int n = 400;  // even
    for (int k = 0; k <= n; ++k) {
      const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
      cost += w * traj.samplePiece(i, T * k / n).snap.squaredNorm() * T / n / 3.0;
    }
  }
  return cost;
}

}  // namespace

TEST(PiecewisePolynomialTrajectory, SnapCostOfKnownPolynomialIsAnalytic) {
  // x = t^5 (snap 120 t), y = t^4 (snap 24), z = 3 (no snap) on [0, 2]:
  // int (120 t)^2 dt = 14400 T^3 / 3 = 38400 and int 24^2 dt = 576 T = 1152.
  PolynomialPiece::Coefficients c = PolynomialPiece::Coefficients::Zero();
  c(5, 0) = 1.0;
  c(4, 1) = 1.0;
  c(0, 2) = 3.0;
  const PiecewisePolynomialTrajectory traj(
      {PiecewisePolynomialTrajectory::pieceFromTimeCoefficients(2.0, c)});
  EXPECT_NEAR(traj.snapCost(), 38400.0 + 1152.0, 1e-6);
  const TrajectorySample s = traj.sample(1.5);
  EXPECT_NEAR(s.position.x(), std::pow(1.5, 5), 1e-12);
  EXPECT_NEAR(s.velocity.x(), 5 * std::pow(1.5, 4), 1e-12);
  EXPECT_NEAR(s.jerk.y(), 24 * 1.5, 1e-12);
  EXPECT_NEAR(s.snap.x(), 120 * 1.5, 1e-12);
  EXPECT_NEAR(s.position.z(), 3.0, 1e-12);
}

TEST(MinimumSnapClosedForm, RestToRestSegmentIsTheKnownSepticAndCost) {
  // The rest-to-rest minimum-snap segment over distance L in time T is
  // L (35 s^4 - 84 s^5 + 70 s^6 - 20 s^7), s = t / T, with cost 100800 L^2 / T^7.
  const double L = 4.0, T = 2.5;
  const MinimumSnapClosedForm fit({Vector3d(1, 2, 3), Vector3d(1 + L, 2, 3)});
  EXPECT_NEAR(fit.cost({T}), 100800.0 * L * L / std::pow(T, 7), 1e-9);
  const PiecewisePolynomialTrajectory traj = fit.trajectory({T});
  const double s = 0.3;
  const double expected =
      L * (35 * std::pow(s, 4) - 84 * std::pow(s, 5) + 70 * std::pow(s, 6) - 20 * std::pow(s, 7));
  EXPECT_NEAR(traj.sample(s * T).position.x() - 1.0, expected, 1e-12);
  EXPECT_NEAR(traj.snapCost(), fit.cost({T}), 1e-9);
}

TEST(MinimumSnapClosedForm, GradientMatchesFiniteDifferences) {
  const MinimumSnapClosedForm fit({Vector3d(0, 0, 1), Vector3d(2, 0, 1), Vector3d(2, 3, 2),
                                   Vector3d(5, 3, 2), Vector3d(6, -1, 1)});
  const std::vector<double> T{1.2, 1.7, 1.1, 2.3};
  std::vector<double> grad;
  fit.cost(T, &grad);
  for (std::size_t i = 0; i < T.size(); ++i) {
    std::vector<double> hi = T, lo = T;
    hi[i] += 1e-6;
    lo[i] -= 1e-6;
    const double fd = (fit.cost(hi) - fit.cost(lo)) / 2e-6;
    EXPECT_NEAR(grad[i], fd, 1e-5 * std::abs(fd) + 1e-8) << "segment " << i;
  }
}

TEST(MinimumSnapClosedForm, PassesWaypointsAtRestEndsAndIsContinuousUpToSnap) {
  const std::vector<Vector3d> w{Vector3d(0, 0, 1), Vector3d(2, 0, 1), Vector3d(2, 3, 2),
                                Vector3d(5, 3, 2)};
  const MinimumSnapClosedForm fit(w);
  const PiecewisePolynomialTrajectory traj = fit.trajectory({1.0, 2.0, 1.5});
  EXPECT_NEAR(traj.duration(), 4.5, 1e-12);
  const TrajectorySample start = traj.samplePiece(0, 0.0), end = traj.samplePiece(2, 1.5);
  EXPECT_LT(start.velocity.norm() + start.acceleration.norm() + start.jerk.norm(), 1e-9);
  EXPECT_LT(end.velocity.norm() + end.acceleration.norm() + end.jerk.norm(), 1e-9);
  EXPECT_LT((end.position - w.back()).norm(), 1e-9);
  for (std::size_t i = 0; i + 1 < traj.pieces().size(); ++i) {
    const TrajectorySample a = traj.samplePiece(i, traj.pieces()[i].duration);
    const TrajectorySample b = traj.samplePiece(i + 1, 0.0);
    EXPECT_LT((a.position - w[i + 1]).norm(), 1e-9);
    EXPECT_LT((a.velocity - b.velocity).norm(), 1e-8);
    EXPECT_LT((a.acceleration - b.acceleration).norm(), 1e-8);
    EXPECT_LT((a.jerk - b.jerk).norm(), 1e-7);
    // Snap is not constrained, but optimal free derivatives make it continuous too.
    EXPECT_LT((a.snap - b.snap).norm(), 1e-6 * (1.0 + a.snap.norm()));
  }
  EXPECT_NEAR(traj.snapCost(), numericSnapCost(traj), 1e-6 * traj.snapCost());
}

TEST(MinimumSnapClosedForm, FreeDerivativesAreOptimal) {
  // The optimal curve through w, split at one of its own points, is still optimal (so the cost is
  // unchanged); any other curve through w, such as one forced through a nearby point, costs more.
  const std::vector<Vector3d> w{Vector3d(0, 0, 0), Vector3d(3, 1, 0), Vector3d(4, 4, 0)};
  const MinimumSnapClosedForm fit(w);
  const std::vector<double> T{2.0, 2.0};
  const PiecewisePolynomialTrajectory traj = fit.trajectory(T);
  const double J = fit.cost(T);
  const Vector3d on_curve = traj.sample(1.0).position;
  const MinimumSnapClosedForm refit({w[0], on_curve, w[1], w[2]});
  EXPECT_NEAR(refit.cost({1.0, 1.0, 2.0}), J, 1e-9 * J);
  const MinimumSnapClosedForm off({w[0], on_curve + Vector3d(0.05, 0, 0), w[1], w[2]});
  EXPECT_GT(off.cost({1.0, 1.0, 2.0}), J * 1.0001);
}

TEST(SegmentTimeAllocation, LowersCostAgainstDistanceProportionalTimes) {
  // Short zig-zags then a long straight: distance-proportional times give the short segments
  // too little time for their sharp turns.
  const MinimumSnapClosedForm fit({Vector3d(0, 0, 1), Vector3d(0.5, 0.5, 1), Vector3d(1, 0, 1),
                                   Vector3d(1.5, 0.5, 1), Vector3d(10, 0.5, 1),
                                   Vector3d(10, 6, 1)});
  const double k_T = 100.0;
  const std::vector<double> initial = distanceProportionalTimes(fit, k_T);
  const TimeAllocationResult r = optimizeSegmentTimes(fit, initial, k_T, 400);
  EXPECT_LT(r.final_cost, 0.8 * r.initial_cost);
  // At the optimum 7 J = k_T sum T (J is homogeneous of degree -7 in time).
  double total = 0.0;
  for (double t : r.durations) total += t;
  EXPECT_NEAR(7.0 * fit.cost(r.durations), k_T * total, 1e-3 * k_T * total);
  // For the same total time, the optimised split has less snap than the proportional one.
  double initial_total = 0.0;
  for (double t : initial) initial_total += t;
  std::vector<double> same_total = initial;
  for (double& t : same_total) t *= total / initial_total;
  EXPECT_LT(fit.cost(r.durations), 0.8 * fit.cost(same_total));
}

TEST(MinimumSnapTrajectory, MeetsSpeedAndAccelerationLimitsWithOneReached) {
  MinimumSnapOptions options;
  options.limits.max_speed = 2.0;
  options.limits.max_acceleration = 3.0;
  const Path path{{Vector3d(0, 0, 1), Vector3d(8, 0, 1), Vector3d(8, 8, 3), Vector3d(0, 8, 1)}};
  const MinimumSnapResult r = MinimumSnapTrajectory(options).fit(path);
  ASSERT_TRUE(r.success) << r.message;
  const TrajectoryPeaks peaks = samplePeaks(r.trajectory, 9.81, 400);
  EXPECT_LE(peaks.speed, 2.0 * 1.01);
  EXPECT_LE(peaks.acceleration, 3.0 * 1.01);
  // fill_limits: the binding limit is reached (up to sampling).
  EXPECT_GT(std::max(peaks.speed / 2.0, peaks.acceleration / 3.0), 0.98);
  EXPECT_LT((r.trajectory.sample(r.trajectory.duration()).position - path.waypoints.back()).norm(),
            1e-9);
}

TEST(MinimumSnapTrajectory, ThrustLimitSlowsAVerticalClimb) {
  MinimumSnapOptions options;
  options.limits.max_speed = 20.0;
  options.limits.max_acceleration = 20.0;
  options.limits.max_thrust_accel = 11.0;  // only 1.19 m/s^2 above gravity
  const Path path{{Vector3d(0, 0, 1), Vector3d(0, 0, 11)}};
  const MinimumSnapResult r = MinimumSnapTrajectory(options).fit(path);
  ASSERT_TRUE(r.success);
  const TrajectoryPeaks peaks = samplePeaks(r.trajectory, 9.81, 2000);
  EXPECT_LE(peaks.thrust_accel, 11.0 * 1.001);
  EXPECT_GT(peaks.thrust_accel, 11.0 * 0.999);
  EXPECT_LT(peaks.acceleration, 3.0);  // far from the acceleration limit: thrust binds
}

TEST(MinimumSnapTrajectory, InfeasibleLimitsAreAClearError) {
  MinimumSnapOptions options;
  options.limits.max_speed = 0.0;
  try {
    MinimumSnapTrajectory{options};
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "max_speed");
  }
  options.limits.max_speed = 3.0;
  options.limits.max_thrust_accel = 9.0;  // cannot hover
  EXPECT_THROW(MinimumSnapTrajectory{options}, InputError);
  options.limits.max_thrust_accel = 20.0;
  options.limits.max_acceleration = -1.0;
  EXPECT_THROW(MinimumSnapTrajectory{options}, InputError);
}

TEST(WaypointThinning, GridStaircaseBecomesOneSegmentInOpenSpace) {
  std::vector<Vector3d> cells;
  for (int i = 0; i <= 10; ++i) {
    cells.emplace_back(i, i, 1);
    if (i < 10) cells.emplace_back(i + 1, i, 1);
  }
  cells.insert(cells.begin() + 3, cells[2]);  // a duplicate
  World world;
  world.bounds_min = Vector3d(-1, -1, 0);
  world.bounds_max = Vector3d(12, 12, 3);
  const InflatedWorld inflated(world, 0.3, cells);
  const std::vector<Vector3d> thin =
      shortcutWaypoints(dropDuplicateWaypoints(cells, 1e-6), inflated);
  ASSERT_EQ(thin.size(), 2u);
  EXPECT_EQ(thin.back(), Vector3d(10, 10, 1));
  // Collinear dropping alone keeps only the corners of a straight run.
  const std::vector<Vector3d> line{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(2, 0, 0),
                                   Vector3d(3, 0, 0), Vector3d(3, 1, 0), Vector3d(3, 2, 0)};
  EXPECT_EQ(dropCollinearWaypoints(line, 1e-6).size(), 3u);
}

namespace {

// An L-shaped path turning left at (5, 0). A minimum-snap curve through the corner waypoint swings
// wide of it (about 0.7 m to the right of the first leg here), into a box that the straight path
// clears by 0.5 m.
World cornerWorld() {
  World world;
  world.bounds_min = Vector3d(-1, -1, 0);
  world.bounds_max = Vector3d(7, 7, 3);
  Obstacle box;
  box.type = ObstacleType::Box;
  box.pos = Vector3d(3.0, -0.95, 1.0);
  box.size = Vector3d(1.0, 0.9, 2.0);  // x in [2.5, 3.5], y in [-1.4, -0.5]
  world.obstacles.push_back(box);
  return world;
}

// Dense check independent of InflatedWorld: every millisecond of the trajectory.
double minimumClearance(const PiecewisePolynomialTrajectory& traj, const World& world) {
  double d = 1e9;
  for (double t = 0.0; t <= traj.duration(); t += 1e-3)
    d = std::min(d, world.distanceToObstacles(traj.sample(t).position));
  return d;
}

}  // namespace

TEST(MinimumSnapTrajectory, CornerOvershootIntoAnObstacleIsRepairedAndClear) {
  const World world = cornerWorld();
  const double inflation = 0.3;
  const Path path{{Vector3d(0, 0, 1), Vector3d(5, 0, 1), Vector3d(5, 5, 1)}};
  MinimumSnapOptions options;
  options.shortcut = false;  // keep the corner so the repair is what clears it
  const MinimumSnapTrajectory generator(options);
  // Without repair the curve swings into the inflated box.
  const MinimumSnapResult plain = generator.fit(path);
  ASSERT_TRUE(plain.success);
  ASSERT_LT(minimumClearance(plain.trajectory, world), inflation);

  const MinimumSnapResult repaired = generator.fit(path, world, inflation);
  ASSERT_TRUE(repaired.success) << repaired.message;
  EXPECT_GE(repaired.counters.at("repair_rounds"), 1.0);
  EXPECT_GT(repaired.waypoints.size(), path.size());
  EXPECT_GT(minimumClearance(repaired.trajectory, world), inflation);
}

TEST(MinimumSnapTrajectory, PathThroughAWallFailsWithAClearMessage) {
  World world = cornerWorld();
  const Path path{{Vector3d(1, -0.9, 1), Vector3d(5, -0.9, 1)}};  // straight through the box
  MinimumSnapOptions options;
  options.max_repair_rounds = 3;
  const MinimumSnapResult r = MinimumSnapTrajectory(options).fit(path, world, 0.3);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("is itself not clear"), std::string::npos) << r.message;
  EXPECT_EQ(r.counters.at("repair_rounds"), 3.0);
}

TEST(MinimumSnapTrajectory, StartEqualsGoalHoldsThePoint) {
  const MinimumSnapResult r =
      MinimumSnapTrajectory().fit(Path{{Vector3d(1, 2, 3), Vector3d(1, 2, 3)}});
  ASSERT_TRUE(r.success);
  EXPECT_EQ(r.trajectory.duration(), 0.0);
  EXPECT_EQ(r.trajectory.sample(5.0).position, Vector3d(1, 2, 3));
}

// A waypoint the user asked to visit survives thinning: line-of-sight shortcuts and straight-run
// merging work between such points, never past them.
TEST(MinimumSnapTrajectory, ShortcutsNeverSkipAViaPoint) {
  const World world = cornerWorld();
  // A detour out to y = 6 and back: in the open, the shortcut goes straight to the goal.
  const Path path{{Vector3d(0, 1, 1), Vector3d(0, 6, 1), Vector3d(1, 6, 1), Vector3d(2, 1, 1)}};
  const MinimumSnapTrajectory generator;
  const MinimumSnapResult free_to_cut = generator.fit(path, world, 0.3);
  ASSERT_TRUE(free_to_cut.success) << free_to_cut.message;
  EXPECT_EQ(free_to_cut.waypoints.size(), 2u);

  const MinimumSnapResult kept = generator.fit(path, world, 0.3, {1});
  ASSERT_TRUE(kept.success) << kept.message;
  ASSERT_GE(kept.waypoints.size(), 3u);
  EXPECT_EQ(kept.waypoints.waypoints[1], Vector3d(0, 6, 1));
  // The curve passes through it.
  double nearest = 1e9;
  for (double t = 0; t <= kept.trajectory.duration(); t += 0.01)
    nearest = std::min(nearest, (kept.trajectory.sample(t).position - Vector3d(0, 6, 1)).norm());
  EXPECT_LT(nearest, 0.02);
}
