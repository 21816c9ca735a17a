#include "experiments/reproduce/seed004_environments.h"

#include <random>

#include "core/input_error.h"
#include "planning/mapf/maze_generator.h"

namespace cosim {

const char* seed004EnvironmentName(Seed004Environment e) {
  switch (e) {
    case Seed004Environment::kMaze:
      return "maze";
    case Seed004Environment::kOpen:
      return "open";
    case Seed004Environment::kBottleneck:
      return "bottleneck";
  }
  return "?";
}

OccupancyGrid seed004Map(Seed004Environment e, int width, int height, std::uint64_t seed) {
  if (e == Seed004Environment::kMaze) return generateMaze(width, height, seed);
  OccupancyGrid grid(width, height);
  if (e == Seed004Environment::kBottleneck) {
    const int wall = width / 2;
    for (int y = 0; y < height; ++y) grid.setBlocked(wall, y, 0, y != height / 2);
  }
  return grid;
}

MapfInstance randomlyPlacedRobots(const OccupancyGrid& grid, int robots, std::uint64_t seed,
                                  int connectivity) {
  std::vector<Cell> free_cells;
  for (int y = 0; y < grid.ny(); ++y)
    for (int x = 0; x < grid.nx(); ++x)
      if (grid.free({x, y, 0})) free_cells.push_back({x, y, 0});
  if (static_cast<int>(free_cells.size()) < robots)
    throw InputError("", "robots", "more robots than free cells");
  std::mt19937_64 rng(seed);
  // Partial Fisher-Yates shuffles (portable, unlike std::shuffle's distribution use).
  const auto pick = [&](std::vector<Cell> cells) {
    for (int i = 0; i < robots; ++i) std::swap(cells[i], cells[i + rng() % (cells.size() - i)]);
    cells.resize(robots);
    return cells;
  };
  MapfInstance inst;
  inst.grid = grid;
  inst.connectivity = connectivity;
  inst.starts = pick(free_cells);
  inst.goals = pick(free_cells);
  return inst;
}

}  // namespace cosim
