#include "experiments/reproduce/seed003_maps.h"

#include <cmath>

namespace cosim {

namespace {

// A box covering cells [x0, x1) x [y0, y1) x [z0, z1) (metres on the 1 m lattice).
Obstacle cellBox(int x0, int x1, int y0, int y1, int z0, int z1) {
  Obstacle o;
  o.type = ObstacleType::Box;
  o.pos = Eigen::Vector3d(x0 + x1, y0 + y1, z0 + z1) / 2.0;
  o.size = Eigen::Vector3d(x1 - x0, y1 - y0, z1 - z0);
  return o;
}

// The centre of the thesis's 1-based cell index [i, j, k].
Eigen::Vector3d cellCentre(int i, int j, int k) {
  return {i - 0.5, j - 0.5, k - 0.5};
}

}  // namespace

std::vector<Seed003Map> seed003Maps() {
  // (name, description, extent in metres, boxes, thesis start and goal cells, planar)
  auto make = [](const char* name, const char* description, Eigen::Vector3d extent,
                 std::vector<Obstacle> boxes, Eigen::Vector3d start, Eigen::Vector3d goal,
                 bool planar) {
    Seed003Map m;
    m.name = name;
    m.description = description;
    m.world.bounds_min = Eigen::Vector3d::Zero();
    m.world.bounds_max = extent;
    m.world.obstacles = std::move(boxes);
    m.start = start;
    m.goal = goal;
    m.planar = planar;
    return m;
  };
  std::vector<Seed003Map> maps;
  maps.push_back(make(
      "2d",
      "25 x 25 m, 1 m cells, 3 obstacles, start [3,3], goal [24,23] (Tab. 1). Reconstructed: "
      "two staggered walls from opposite sides force an S-shaped detour and a block guards the "
      "goal; the map is one layer (2 m tall boxes) for ground robots.",
      {25, 25, 2},
      {cellBox(0, 12, 8, 10, 0, 2), cellBox(13, 25, 14, 16, 0, 2), cellBox(18, 23, 18, 20, 0, 2)},
      cellCentre(3, 3, 1), cellCentre(24, 23, 1), true));
  maps.push_back(make(
      "3d-1",
      "20 x 20 x 15 m, 2 obstacles inside, the space enclosed by a boundary, start [3,3,3], "
      "goal [17,17,15] (Tab. 2). Reconstructed: a 1 m wall on each side as the boundary; a "
      "wall open only at the top, then a wall open only at the bottom, so the path goes over "
      "the first and under the second.",
      {20, 20, 15},
      {cellBox(0, 20, 0, 1, 0, 15), cellBox(0, 20, 19, 20, 0, 15), cellBox(0, 1, 1, 19, 0, 15),
       cellBox(19, 20, 1, 19, 0, 15), cellBox(7, 9, 1, 19, 0, 10), cellBox(12, 14, 1, 19, 5, 15)},
      cellCentre(3, 3, 3), cellCentre(17, 17, 15), false));
  maps.push_back(make(
      "3d-2",
      "20 x 20 x 10 m, start [2,19,2] and goal [9,13,9] close but separated by obstacles, most "
      "free space on the far side (Tab. 3). Reconstructed: a floor-to-mid slab over most of "
      "the map with an opening only on the far (high x) side, and a wall on top of the slab "
      "that leaves a passage only along the high-y edge.",
      {20, 20, 10}, {cellBox(0, 17, 0, 20, 4, 6), cellBox(9, 13, 0, 18, 6, 10)},
      cellCentre(2, 19, 2), cellCentre(9, 13, 9), false));
  maps.push_back(make(
      "3d-3",
      "50 x 50 x 5 m, the most obstacles, a 'problematic' layout, start [3,2,2], goal "
      "[47,47,4] (Tab. 4). Reconstructed: three full-height walls alternately open at opposite "
      "ends (a zig-zag) and two low blocks that can be overflown.",
      {50, 50, 5},
      {cellBox(10, 12, 0, 26, 0, 5), cellBox(22, 24, 20, 50, 0, 5), cellBox(34, 36, 0, 33, 0, 5),
       cellBox(14, 20, 8, 14, 0, 3), cellBox(38, 46, 38, 44, 0, 3)},
      cellCentre(3, 2, 2), cellCentre(47, 47, 4), false));
  return maps;
}

OccupancyGrid seed003Grid(const Seed003Map& map) {
  const World& w = map.world;
  const Eigen::Vector3d extent = w.bounds_max - w.bounds_min;
  const int nx = static_cast<int>(std::lround(extent.x()));
  const int ny = static_cast<int>(std::lround(extent.y()));
  const int nz = map.planar ? 1 : static_cast<int>(std::lround(extent.z()));
  OccupancyGrid grid(nx, ny, nz, 1.0, w.bounds_min);
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        Eigen::Vector3d c = grid.cellCenter({x, y, z});
        if (map.planar) c.z() = map.start.z();
        for (const Obstacle& o : w.obstacles)
          if (o.signedDistance(c) < 0.0) {
            grid.setBlocked(x, y, z, true);
            break;
          }
      }
  return grid;
}

}  // namespace cosim
