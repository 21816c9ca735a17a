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

namespace {

// The free cells with x in [x_from, x_to).
std::vector<Cell> freeCells(const OccupancyGrid& grid, int x_from, int x_to, int robots) {
  std::vector<Cell> cells;
  for (int y = 0; y < grid.ny(); ++y)
    for (int x = x_from; x < x_to; ++x)
      if (grid.free({x, y, 0})) cells.push_back({x, y, 0});
  if (static_cast<int>(cells.size()) < robots)
    throw InputError("", "robots", "more robots than free cells");
  return cells;
}

// `robots` distinct cells of `cells`: a partial Fisher-Yates shuffle (portable, unlike
// std::shuffle's distribution use).
std::vector<Cell> pickCells(std::vector<Cell> cells, int robots, std::mt19937_64& rng) {
  for (int i = 0; i < robots; ++i) std::swap(cells[i], cells[i + rng() % (cells.size() - i)]);
  cells.resize(robots);
  return cells;
}

}  // namespace

MapfInstance randomlyPlacedRobots(const OccupancyGrid& grid, int robots, std::uint64_t seed,
                                  int connectivity) {
  const std::vector<Cell> free_cells = freeCells(grid, 0, grid.nx(), robots);
  std::mt19937_64 rng(seed);
  MapfInstance inst;
  inst.grid = grid;
  inst.connectivity = connectivity;
  inst.starts = pickCells(free_cells, robots, rng);
  inst.goals = pickCells(free_cells, robots, rng);
  return inst;
}

MapfInstance robotsThroughTheDoor(const OccupancyGrid& grid, int robots, std::uint64_t seed,
                                  int connectivity) {
  const int wall = grid.nx() / 2;
  std::mt19937_64 rng(seed);
  MapfInstance inst;
  inst.grid = grid;
  inst.connectivity = connectivity;
  inst.starts = pickCells(freeCells(grid, 0, wall, robots), robots, rng);
  inst.goals = pickCells(freeCells(grid, wall + 1, grid.nx(), robots), robots, rng);
  return inst;
}

}  // namespace cosim
