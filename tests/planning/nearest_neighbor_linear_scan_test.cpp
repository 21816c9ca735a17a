// The linear-scan nearest-neighbour search (rrt_star_thesis's neighbour_search: linear, which
// reproduces seed 003's cost structure) answers every query as the k-d tree does.
#include <gtest/gtest.h>

#include <random>

#include "planning/sampling/nearest_neighbor_index.h"

namespace cosim {
namespace {

TEST(NearestNeighborIndex, LinearScanAnswersAsTheKdTreeWithRemovals) {
  NearestNeighborIndex tree(64), scan(64, true);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 10.0);
  for (int i = 0; i < 300; ++i) {
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    EXPECT_EQ(tree.add(p), scan.add(p));
    if (i % 7 == 3) {
      tree.remove(static_cast<std::uint32_t>(i - 2));
      scan.remove(static_cast<std::uint32_t>(i - 2));
    }
  }
  ASSERT_EQ(tree.size(), scan.size());
  std::vector<std::pair<std::uint32_t, double>> a, b;
  for (int k = 0; k < 50; ++k) {
    const Eigen::Vector3d q(u(rng), u(rng), u(rng));
    EXPECT_EQ(tree.nearest(q), scan.nearest(q));
    tree.withinRadius(q, 2.0, a);
    scan.withinRadius(q, 2.0, b);
    EXPECT_EQ(a, b);
    tree.nearestK(q, 6, a);
    scan.nearestK(q, 6, b);
    EXPECT_EQ(a, b);
  }
}

}  // namespace
}  // namespace cosim
