// A grid map as a world of boxes (planning/world/grid_map_world.h).
#include "planning/world/grid_map_world.h"

#include <gtest/gtest.h>

#include "planning/grid/movingai.h"

namespace cosim {
namespace {

OccupancyGrid scaled(const OccupancyGrid& g, double cell) {
  OccupancyGrid out(g.nx(), g.ny(), 1, cell);
  for (int y = 0; y < g.ny(); ++y)
    for (int x = 0; x < g.nx(); ++x) out.setBlocked(x, y, 0, g.blocked(x, y));
  return out;
}

// Every blocked cell's centre lies inside a box and every free cell's centre outside all boxes,
// at a cell size that is not 1 (so a forgotten scale shows).
void expectBoxesCoverExactlyTheBlockedCells(const OccupancyGrid& grid, const World& w) {
  for (int y = 0; y < grid.ny(); ++y)
    for (int x = 0; x < grid.nx(); ++x) {
      Eigen::Vector3d p = grid.cellCenter({x, y, 0});
      p.z() = 0.1;
      EXPECT_EQ(w.distanceToObstacles(p) < 0.0, grid.blocked(x, y)) << "cell " << x << "," << y;
    }
}

TEST(GridMapWorld, BoxesCoverExactlyTheBlockedCellsOfTheWarehouseMap) {
  const OccupancyGrid grid =
      scaled(readMovingAIMap(COSIM_SOURCE_DIR "/experiments/maps/warehouse-10-20-10-2-1.map"), 0.5);
  const World w = worldFromGridMap(grid, 0.4, 3.0);
  expectBoxesCoverExactlyTheBlockedCells(grid, w);
  EXPECT_DOUBLE_EQ(w.bounds_max.x(), 0.5 * grid.nx());
  EXPECT_DOUBLE_EQ(w.bounds_max.y(), 0.5 * grid.ny());
  EXPECT_DOUBLE_EQ(w.bounds_max.z(), 3.0);
  // The map's shelves are 10x2-cell blocks: merged, far fewer boxes than blocked cells.
  EXPECT_LT(w.obstacles.size() * 10, grid.blockedCount());
}

TEST(GridMapWorld, BoxesCoverExactlyTheBlockedCellsOfTheMazeMap) {
  const OccupancyGrid grid =
      scaled(readMovingAIMap(COSIM_SOURCE_DIR "/experiments/maps/maze-32-32-2.map"), 0.7);
  const World w = worldFromGridMap(grid, 0.5, 2.0);
  expectBoxesCoverExactlyTheBlockedCells(grid, w);
  EXPECT_LT(w.obstacles.size(), grid.blockedCount());
  for (const Obstacle& o : w.obstacles) EXPECT_DOUBLE_EQ(o.pos.z(), 0.25);
}

TEST(GridMapWorld, AnL_ShapeBecomesTwoBoxes) {
  OccupancyGrid grid(4, 3, 1, 1.0);
  // ##..
  // #...
  // #...
  grid.setBlocked(0, 0, 0, true);
  grid.setBlocked(1, 0, 0, true);
  grid.setBlocked(0, 1, 0, true);
  grid.setBlocked(0, 2, 0, true);
  const World w = worldFromGridMap(grid, 1.0, 2.0);
  ASSERT_EQ(w.obstacles.size(), 2u);
  EXPECT_EQ(w.obstacles[0].size, Eigen::Vector3d(2.0, 1.0, 1.0));
  EXPECT_EQ(w.obstacles[1].size, Eigen::Vector3d(1.0, 2.0, 1.0));
  EXPECT_EQ(w.obstacles[1].pos, Eigen::Vector3d(0.5, 2.0, 0.5));
}

}  // namespace
}  // namespace cosim
