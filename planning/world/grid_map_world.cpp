#include "planning/world/grid_map_world.h"

#include <string>
#include <vector>

#include "core/input_error.h"

namespace cosim {

World worldFromGridMap(const OccupancyGrid& grid, double height, double ceiling,
                       std::size_t max_boxes) {
  const double c = grid.cellSize();
  const Eigen::Vector3d origin = grid.origin();
  World world;
  world.bounds_min = {origin.x(), origin.y(), 0.0};
  world.bounds_max = {origin.x() + c * grid.nx(), origin.y() + c * grid.ny(), ceiling};

  // Greedy rectangles: from each blocked cell not yet covered (row by row), take the longest run
  // of uncovered blocked cells to the right, then grow it down while the next row has the same
  // run. Warehouse shelves and maze walls become one box each instead of one per cell (MuJoCo's
  // collision phase and the clearance metric scale with the number of geoms).
  std::vector<bool> covered(static_cast<std::size_t>(grid.nx()) * grid.ny(), false);
  const auto open = [&](int x, int y) {
    return grid.blocked(x, y) && !covered[static_cast<std::size_t>(y) * grid.nx() + x];
  };
  for (int y = 0; y < grid.ny(); ++y)
    for (int x = 0; x < grid.nx(); ++x) {
      if (!open(x, y)) continue;
      if (world.obstacles.size() >= max_boxes)
        throw InputError("", "",
                         "the map's blocked cells make more than " + std::to_string(max_boxes) +
                             " boxes (scattered cells each need one); use a map with fewer, "
                             "larger obstacles");
      int x1 = x;
      while (x1 + 1 < grid.nx() && open(x1 + 1, y)) ++x1;
      int y1 = y;
      for (;;) {
        if (y1 + 1 >= grid.ny()) break;
        bool full = true;
        for (int k = x; k <= x1 && full; ++k) full = open(k, y1 + 1);
        if (!full) break;
        ++y1;
      }
      for (int j = y; j <= y1; ++j)
        for (int k = x; k <= x1; ++k) covered[static_cast<std::size_t>(j) * grid.nx() + k] = true;
      Obstacle box;
      box.type = ObstacleType::Box;
      box.size = {c * (x1 - x + 1), c * (y1 - y + 1), height};
      box.pos = {origin.x() + c * (0.5 * (x + x1) + 0.5), origin.y() + c * (0.5 * (y + y1) + 0.5),
                 0.5 * height};
      world.obstacles.push_back(box);
    }
  return world;
}

}  // namespace cosim
