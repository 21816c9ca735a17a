// A 3D grid drawn from above shows each column's height: a wall standing on a slab (3D map 2 of
// seed 003) comes out as two shades, not one grey square.
#include <gtest/gtest.h>

#include <set>

#include "experiments/reproduce/reproduction_map.h"

namespace cosim::reproduce {
namespace {

TEST(ReproductionMapHeights, AWallOnASlabGetsItsOwnTop) {
  OccupancyGrid grid(6, 4, 8);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 6; ++x) grid.setBlocked(x, y, 0, true);  // a slab 1 cell high
  for (int y = 0; y < 4; ++y)
    for (int z = 1; z < 5; ++z) grid.setBlocked(3, y, z, true);  // a wall on it, up to 5
  const ReproductionMap m = gridMap("slab and wall", grid, {0, 0, 1}, {5, 3, 1});
  EXPECT_TRUE(m.blocks.empty());
  EXPECT_EQ(m.height_max, 8);
  std::set<double> tops;
  int wall_cells = 0;
  for (const auto& b : m.height_blocks) {
    tops.insert(b.top);
    if (b.top == 5)
      wall_cells += static_cast<int>((b.rect[2] - b.rect[0]) * (b.rect[3] - b.rect[1]));
  }
  EXPECT_EQ(tops, (std::set<double>{1, 5}));
  EXPECT_EQ(wall_cells, 4);  // the wall's column x = 3, all four rows
}

TEST(ReproductionMapHeights, TwoDimensionalGridsKeepPlainBlocks) {
  OccupancyGrid grid(5, 5);
  grid.setBlocked(2, 2, 0, true);
  const ReproductionMap m = gridMap("one cell", grid, {0, 0, 0}, {4, 4, 0});
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_TRUE(m.height_blocks.empty());
}

}  // namespace
}  // namespace cosim::reproduce
