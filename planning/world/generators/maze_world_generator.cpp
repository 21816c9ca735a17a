#include "planning/world/generators/maze_world_generator.h"

#include <cmath>

#include "core/input_error.h"
#include "planning/mapf/maze_generator.h"

namespace cosim {

GeneratedWorld generateMazeWorld(const MazeWorldOptions& o) {
  checkWorldGeneratorOptions(o.world, 1.0, "maze");
  const Eigen::Vector3d size = o.world.size;
  if (!(o.cell > 0)) throw InputError("", "generator maze", "cell must be positive");
  const int nx = static_cast<int>(std::floor(size.x() / o.cell));
  const int ny = static_cast<int>(std::floor(size.y() / o.cell));
  if (nx < 3 || ny < 3 || size.z() < 1)
    throw InputError("", "generator maze", "fewer than 3 x 3 cells fit (size / cell)");
  // Walls are merged along rows into boxes: at most one box per two cells.
  checkGeneratedObstacleCount(0.5 * nx * ny, "maze");
  OccupancyGrid maze = generateMaze(nx, ny, o.world.seed);

  // Open loops: a wall cell with exactly one odd coordinate separates two corridor cells; keep it
  // with probability `density`. A separate stream (seed + 1) leaves the maze itself unchanged.
  std::mt19937_64 rng(o.world.seed + 1);
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      const bool between_x = x % 2 == 1 && y % 2 == 0 && x + 1 < nx;
      const bool between_y = y % 2 == 1 && x % 2 == 0 && y + 1 < ny;
      if (!between_x && !between_y) continue;
      const bool keep = unitDraw(rng) < o.world.density;
      if (!keep && maze.blocked(x, y, 0)) maze.setBlocked(x, y, 0, false);
    }

  GeneratedWorld g;
  g.world.bounds_min = Eigen::Vector3d::Zero();
  // The bounds are the maze's own extent: a band of free space around it would be a way round.
  g.world.bounds_max = {nx * o.cell, ny * o.cell, size.z()};
  const double z = size.z() / 2;
  g.start = {0.5 * o.cell, 0.5 * o.cell, z};
  const int gx = (nx - 1) % 2 == 0 ? nx - 1 : nx - 2;
  const int gy = (ny - 1) % 2 == 0 ? ny - 1 : ny - 2;
  g.goal = {(gx + 0.5) * o.cell, (gy + 0.5) * o.cell, z};
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx;) {
      if (!maze.blocked(x, y, 0)) {
        ++x;
        continue;
      }
      int end = x;
      while (end < nx && maze.blocked(end, y, 0)) ++end;
      Obstacle w;
      w.type = ObstacleType::Box;
      w.pos = {0.5 * (x + end) * o.cell, (y + 0.5) * o.cell, size.z() / 2};
      w.size = {(end - x) * o.cell, o.cell, size.z()};
      g.world.obstacles.push_back(w);
      x = end;
    }
  return g;
}

}  // namespace cosim
