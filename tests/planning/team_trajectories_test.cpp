// Smoothing a lock-step team plan into trajectories keeps the schedule, the separation between
// every pair and the clearance to obstacles in continuous time.
#include "planning/team/team_trajectories.h"

#include <gtest/gtest.h>

using namespace cosim;
using Eigen::Vector3d;

namespace {

World emptyRoom() {
  World w;
  w.bounds_min = {-10, -10, 0};
  w.bounds_max = {10, 10, 5};
  return w;
}

// The smallest ellipsoidal distance between two trajectories, sampled every millisecond.
double closest(const PiecewisePolynomialTrajectory& a, const PiecewisePolynomialTrajectory& b,
               const SeparationEllipsoid& e) {
  double d = 1e9;
  for (double t = 0; t <= std::max(a.duration(), b.duration()); t += 0.001)
    d = std::min(d, e.distance(a.sample(t).position, b.sample(t).position));
  return d;
}

}  // namespace

TEST(TeamTrajectories, AStraightRunFliesOnScheduleWithoutStopping) {
  // Five cells in a row, 0.5 m apart, one step each: the agent passes cell k at t = k without
  // stopping in between.
  TeamMember a;
  for (int k = 0; k < 5; ++k) a.points.push_back({0.5 * k, 0, 2});
  TeamTrajectoryOptions o;
  const TeamTrajectories r = smoothTeamPaths({a}, emptyRoom(), o);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ(r.stops_added, 0);
  for (int k = 0; k < 5; ++k)
    EXPECT_LT((r.trajectories[0].sample(k).position - a.points[k]).norm(), 1e-9) << k;
  // Held to the schedule from rest, it runs ahead of the average 0.5 m/s and waits for the
  // next cell; never faster than a rest-to-rest segment's peak, 35/16 x 0.5 m/s.
  double peak = 0.0;
  for (double t = 0; t <= 4.0; t += 0.001)
    peak = std::max(peak, r.trajectories[0].sample(t).velocity.norm());
  EXPECT_GT(peak, 0.5);
  EXPECT_LT(peak, 35.0 / 16.0 * 0.5);
}

TEST(TeamTrajectories, AnAgentCuttingACornerTowardsAnotherIsMadeToStopAndKeepsTheSeparation) {
  // B hovers at (0, c); A flies (0, 0) -> (c, 0) and turns up at (c, 0). Along the grid path A
  // stays 1.08 separations from B; smoothed freely it cuts the corner to 0.94 of one.
  const SeparationEllipsoid e{0.24, 0.6};
  const double c = 0.26;
  TeamMember a, b;
  a.separation = b.separation = e;
  a.points = {{0, 0, 2}, {c, 0, 2}, {c, c, 2}, {c, 2 * c, 2}, {c, 3 * c, 2}};
  b.points = {{0, c, 2}};
  TeamTrajectoryOptions free;
  free.max_repair_rounds = 0;
  EXPECT_NEAR(smoothTeamPaths({a, b}, emptyRoom(), free).min_separation, 0.943, 0.005);
  TeamTrajectoryOptions o;
  const TeamTrajectories r = smoothTeamPaths({a, b}, emptyRoom(), o);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_GT(r.stops_added, 0);
  EXPECT_GE(closest(r.trajectories[0], r.trajectories[1], e), 1.0 - 1e-3);
}

TEST(TeamTrajectories, ACornerNextToAPillarKeepsTheClearance) {
  // The path turns around a pillar whose surface is 0.35 m from the corner's two legs; the
  // vehicle must keep 0.3 m. Freely smoothed, the corner cut comes closer; repaired, it does not.
  World w = emptyRoom();
  Obstacle pillar;
  pillar.type = ObstacleType::Cylinder;
  pillar.pos = {0.65, 0.65, 2.5};
  pillar.radius = 0.3;
  pillar.height = 5;
  w.obstacles.push_back(pillar);
  TeamMember a;
  a.clearance = 0.3;
  a.points = {{-1, 0, 2}, {0, 0, 2}, {0, 1, 2}, {0, 2, 2}};
  TeamTrajectoryOptions free;
  free.max_repair_rounds = 0;
  EXPECT_LT(smoothTeamPaths({a}, w, free).min_clearance, 0.0);
  const TeamTrajectories r = smoothTeamPaths({a}, w, TeamTrajectoryOptions{});
  ASSERT_TRUE(r.success) << r.message;
  double clear = 1e9;
  for (double t = 0; t <= r.trajectories[0].duration(); t += 0.001)
    clear = std::min(clear, w.distanceToObstacles(r.trajectories[0].sample(t).position));
  EXPECT_GE(clear, 0.3 - 1e-3);
}

TEST(TeamTrajectories, APlanThatItselfViolatesTheSeparationIsReported) {
  // Two agents 0.1 m apart side by side the whole way: no stop can fix that.
  TeamMember a, b;
  a.points = {{0, 0, 2}, {0.5, 0, 2}};
  b.points = {{0, 0.1, 2}, {0.5, 0.1, 2}};
  const TeamTrajectories r = smoothTeamPaths({a, b}, emptyRoom(), TeamTrajectoryOptions{});
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("closer than the separation"), std::string::npos) << r.message;
  EXPECT_NEAR(r.min_separation, 0.1 / 0.24, 1e-6);
}
