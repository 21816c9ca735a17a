#include "planning/mapf/maze_generator.h"

#include <cstdlib>
#include <random>
#include <vector>

#include "core/input_error.h"

namespace cosim {

namespace {

// Draws an index in [0, n) from rng (std::uniform_int_distribution is not portable across
// standard libraries; this is).
std::size_t drawIndex(std::mt19937_64& rng, std::size_t n) {
  return rng() % n;
}

}  // namespace

OccupancyGrid generateMaze(int width, int height, std::uint64_t seed) {
  if (width < 1 || height < 1)
    throw InputError("", "maze size", "width and height must be at least 1");
  OccupancyGrid grid(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) grid.setBlocked(x, y, 0, x % 2 != 0 || y % 2 != 0);
  std::vector<Cell> unvisited, visited;
  for (int y = 0; y < height; y += 2)
    for (int x = 0; x < width; x += 2) unvisited.push_back({x, y, 0});
  std::mt19937_64 rng(seed);
  const auto takeRandom = [&]() {
    const std::size_t i = drawIndex(rng, unvisited.size());
    const Cell c = unvisited[i];
    unvisited[i] = unvisited.back();
    unvisited.pop_back();
    return c;
  };
  visited.push_back(takeRandom());
  while (!unvisited.empty()) {
    const Cell from = takeRandom();
    const Cell* to = &visited.front();
    int best = width + height;
    for (const Cell& v : visited) {
      const int d = std::abs(v.x - from.x) + std::abs(v.y - from.y);
      if (d < best) best = d, to = &v;
    }
    // WYBURZDROGĘ: along x, then along y.
    int x = from.x, y = from.y;
    while (x != to->x) grid.setBlocked(x, y, 0, false), x += x < to->x ? 1 : -1;
    while (y != to->y) grid.setBlocked(x, y, 0, false), y += y < to->y ? 1 : -1;
    visited.push_back(from);
  }
  return grid;
}

}  // namespace cosim
