// CollisionWorld: exact segment tests against the inflated obstacles, checked against the
// obstacles' own signed distance (World::distanceToObstacles) and against hand-computed cases.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "planning/sampling/collision_world.h"
#include "planning/sampling/nearest_neighbor_index.h"

namespace cosim {
namespace {

World mixedWorld(int n, std::uint64_t seed, double size) {
  World w;
  w.bounds_min = {0, 0, 0};
  w.bounds_max = {size, size, 10};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    Obstacle o;
    o.type = static_cast<ObstacleType>(i % 3);
    o.pos = {size * u(rng), size * u(rng), 10 * u(rng)};
    o.size = {0.5 + 3 * u(rng), 0.5 + 3 * u(rng), 0.5 + 4 * u(rng)};
    o.radius = 0.3 + 1.5 * u(rng);
    o.height = 1 + 5 * u(rng);
    o.yaw_deg = 360 * u(rng);
    w.obstacles.push_back(o);
  }
  return w;
}

TEST(SamplingCollisionWorld, SegmentTestAgreesWithDenseSignedDistanceSampling) {
  const World w = mixedWorld(25, 7, 20.0);
  const double inflation = 0.4;
  const CollisionWorld cw(w, inflation);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int hits = 0, misses = 0, grazing = 0;
  for (int i = 0; i < 600; ++i) {
    const Eigen::Vector3d a(20 * u(rng), 20 * u(rng), 10 * u(rng));
    const Eigen::Vector3d b = a + Eigen::Vector3d(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5) * 6;
    if (!cw.insideBounds(b)) continue;
    // Minimum clearance over samples 2 mm apart; the true minimum is within 1 mm of it.
    const int n = static_cast<int>((b - a).norm() / 2e-3) + 1;
    double min_d = 1e9;
    for (int k = 0; k <= n; ++k)
      min_d = std::min(min_d, w.distanceToObstacles(a + (b - a) * k / n));
    const bool free = cw.segmentFree(a, b);
    if (min_d < inflation - 1e-6) {
      EXPECT_FALSE(free) << "segment " << i << " enters an obstacle but was reported free";
      ++hits;
    } else if (min_d > inflation + 2e-3) {
      EXPECT_TRUE(free) << "segment " << i << " clears by " << min_d - inflation;
      ++misses;
    } else {
      ++grazing;
    }
  }
  EXPECT_GT(hits, 80);
  EXPECT_GT(misses, 150);
  EXPECT_LT(grazing, 15);
}

TEST(SamplingCollisionWorld, RoundedCornerOfInflatedBoxIsNotItsBoundingBox) {
  World w;
  w.bounds_min = {-10, -10, -10};
  w.bounds_max = {10, 10, 10};
  Obstacle box;
  box.size = {2, 2, 20};  // x, y in [-1, 1]
  w.obstacles.push_back(box);
  const CollisionWorld cw(w, 0.5);
  // The line x + y = c passes the corner (1, 1) at distance (c - 2) / sqrt(2).
  auto segment = [](double clearance) {
    const double c = 2.0 + clearance * std::sqrt(2.0);
    return std::make_pair(Eigen::Vector3d(c + 5, -5, 0), Eigen::Vector3d(-5, c + 5, 0));
  };
  const auto [a_free, b_free] = segment(0.51);  // inside the inflated bounding square
  EXPECT_TRUE(cw.segmentFree(a_free, b_free));
  const auto [a_hit, b_hit] = segment(0.49);
  EXPECT_FALSE(cw.segmentFree(a_hit, b_hit));
  // Parallel to a face: 0.5 m from the box is touching (not free), 0.501 m is free.
  EXPECT_FALSE(cw.segmentFree({-5, 1.5, 0}, {5, 1.5, 0}));
  EXPECT_TRUE(cw.segmentFree({-5, 1.501, 0}, {5, 1.501, 0}));
}

TEST(SamplingCollisionWorld, CylinderRimIsRoundedByInflation) {
  World w;
  w.bounds_min = {-10, -10, -10};
  w.bounds_max = {10, 10, 10};
  Obstacle cyl;
  cyl.type = ObstacleType::Cylinder;
  cyl.radius = 1.0;
  cyl.height = 2.0;  // z in [-1, 1]
  w.obstacles.push_back(cyl);
  const CollisionWorld cw(w, 0.5);
  // A horizontal segment above the rim at height 1 + h, offset so it passes the rim (radial
  // distance 1 + s from the axis): its distance to the cylinder is hypot(s, h).
  auto free = [&](double s, double h) {
    return cw.segmentFree({1 + s, -5, 1 + h}, {1 + s, 5, 1 + h});
  };
  EXPECT_TRUE(free(0.36, 0.36));   // hypot = 0.509
  EXPECT_FALSE(free(0.35, 0.35));  // hypot = 0.495
  EXPECT_FALSE(free(-0.5, 0.45));  // over the top face
  EXPECT_TRUE(free(-0.5, 0.51));
  // Through the axis, far above the top: free; vertical through the body: not.
  EXPECT_TRUE(cw.segmentFree({0, -5, 1.6}, {0, 5, 1.6}));
  EXPECT_FALSE(cw.segmentFree({0, 0, -5}, {0, 0, 5}));
}

TEST(SamplingCollisionWorld, DistanceAndPointTestsMatchTheWorldWithThousandsOfObstacles) {
  const World w = mixedWorld(3000, 11, 200.0);
  const double inflation = 0.3;
  const CollisionWorld cw(w, inflation);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int blocked = 0;
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d p(200 * u(rng), 200 * u(rng), 10 * u(rng));
    const double expected = w.distanceToObstacles(p);
    EXPECT_NEAR(cw.distanceToObstacles(p), expected, 1e-9);
    EXPECT_EQ(cw.pointFree(p), expected > inflation);
    blocked += expected <= inflation;
  }
  EXPECT_GT(blocked, 20);
  EXPECT_FALSE(cw.pointFree({-1, 5, 5}));  // outside the bounds
}

TEST(SamplingNearestNeighborIndex, AgreesWithBruteForceAfterInsertionsAndRemovals) {
  NearestNeighborIndex index(100);
  std::vector<Eigen::Vector3d> pts;
  std::vector<bool> live;
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 10.0);
  std::vector<std::pair<std::uint32_t, double>> out;
  for (int i = 0; i < 700; ++i) {
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    EXPECT_EQ(index.add(p), static_cast<std::uint32_t>(pts.size()));
    pts.push_back(p);
    live.push_back(true);
    if (i % 3 == 2) {  // remove an earlier point
      const std::uint32_t victim = static_cast<std::uint32_t>(i / 2);
      if (live[victim]) index.remove(victim), live[victim] = false;
    }
    const Eigen::Vector3d q(u(rng), u(rng), u(rng));
    std::uint32_t best = 0;
    double best_d = 1e18;
    int within = 0;
    for (std::uint32_t k = 0; k < pts.size(); ++k) {
      if (!live[k]) continue;
      const double d = (pts[k] - q).squaredNorm();
      if (d < best_d) best_d = d, best = k;
      within += d < 4.0;
    }
    ASSERT_EQ(index.nearest(q), best);
    index.withinRadius(q, 2.0, out);
    ASSERT_EQ(static_cast<int>(out.size()), within);
    index.nearestK(q, 5, out);
    ASSERT_EQ(out.front().first, best);
  }
  EXPECT_EQ(index.size(), static_cast<std::size_t>(std::count(live.begin(), live.end(), true)));
}

}  // namespace
}  // namespace cosim
