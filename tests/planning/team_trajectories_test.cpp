// Smoothing a lock-step team plan into trajectories keeps the schedule, the separation between
// every pair and the clearance to obstacles in continuous time.
#include "planning/team/team_trajectories.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "planning/team/team_pair_candidates.h"

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

namespace {

// A column of `n` agents 0.3 m apart along y (1.25 separations of 0.24 m), all flying 10 steps
// of 0.5 m along x side by side: nobody ever comes near anybody but a neighbour.
std::vector<TeamMember> column(int n) {
  std::vector<TeamMember> team(n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k <= 10; ++k) team[i].points.push_back({0.5 * k - 2.5, 0.3 * i - 0.15 * n, 2});
  return team;
}

World hall() {
  World w;
  w.bounds_min = {-40, -40, 0};
  w.bounds_max = {40, 40, 5};
  return w;
}

}  // namespace

TEST(TeamPairCandidates, EveryPairThatComesWithinReachIsACandidateAndFarPairsAreNot) {
  // Agents on random walks in a 6 m cube, sampled at 20 instants; a pair is a candidate when its
  // scaled boxes (grown by reach / 2) meet, so every pair closer than reach at some instant is
  // one, and a pair whose boxes stay more than reach apart is not.
  std::vector<std::vector<Vector3d>> at(60);
  std::uint64_t state = 12345;
  const auto unit = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  for (auto& a : at) {
    Vector3d p(6 * unit(), 6 * unit(), 6 * unit());
    for (int s = 0; s < 20; ++s) a.push_back(p += 0.05 * Vector3d(unit(), unit(), unit()));
  }
  const Vector3d scale(1 / 0.24, 1 / 0.24, 1 / 0.6);
  const auto pairs = candidatePairs(at, 0, 19, scale, 1.5);
  const SeparationEllipsoid e{0.24, 0.6};
  int close = 0;
  for (std::size_t i = 0; i < at.size(); ++i)
    for (std::size_t j = i + 1; j < at.size(); ++j) {
      double d = 1e9;
      for (int s = 0; s < 20; ++s) d = std::min(d, e.distance(at[i][s], at[j][s]));
      const bool candidate =
          std::binary_search(pairs.begin(), pairs.end(),
                             std::pair<int, int>(static_cast<int>(i), static_cast<int>(j)));
      if (d < 1.5) {
        ++close;
        EXPECT_TRUE(candidate) << i << "," << j << " at " << d;
      }
      // Boxes at most 0.05 x 20 x sqrt(3) m wide: a pair 4.5 separations apart throughout
      // (scaled, beyond reach + both boxes' widths) cannot share a cell.
      if (d > 4.5 + 2 * 20 * 0.05 * std::sqrt(3.0) / 0.24) {
        EXPECT_FALSE(candidate) << i << "," << j;
      }
    }
  EXPECT_GT(close, 0);  // the test sees both kinds
  EXPECT_LT(pairs.size(), at.size() * (at.size() - 1) / 2);
}

TEST(TeamTrajectories, OnlyNeighboursAreCheckedInALargeTeam) {
  // 200 agents in a column: all pairs at all instants would be 19 900 x instants; the spatial
  // hash (reach 1.5 separations) leaves each agent's next one or two in the column.
  const std::vector<TeamMember> team = column(200);
  TeamTrajectoryOptions o;
  const TeamTrajectories r = smoothTeamPaths(team, hall(), o);
  ASSERT_TRUE(r.success) << r.message;
  const long instants = static_cast<long>(std::ceil(10 * o.step_duration / o.check_interval)) + 1;
  EXPECT_LE(r.pair_checks, 2L * 200 * instants);
  EXPECT_GE(r.pair_checks, 199L * instants);  // every neighbouring pair, at every instant
  EXPECT_NEAR(r.min_separation, 0.3 / 0.24, 1e-9);
}

TEST(TeamTrajectories, AStopRequestOrAnExpiredTimeLimitEndsTheSmoothingAtOnce) {
  const std::vector<TeamMember> team = column(50);
  std::atomic<bool> stop{true};
  const StopToken stopped(60.0, &stop);
  TeamTrajectoryOptions o;
  o.deadline = &stopped;
  const TeamTrajectories s = smoothTeamPaths(team, hall(), o);
  EXPECT_FALSE(s.success);
  EXPECT_EQ(s.status, PlannerStatus::Stopped);
  EXPECT_EQ(s.message, "stopped");
  EXPECT_EQ(s.pair_checks, 0);  // not one window checked
  const StopToken expired(0.0);
  o.deadline = &expired;
  const TeamTrajectories t = smoothTeamPaths(team, hall(), o);
  EXPECT_EQ(t.status, PlannerStatus::Timeout);
  EXPECT_EQ(t.message, "time limit reached");
}
