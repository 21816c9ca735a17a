#include "planning/navigation/randomly_turning_obstacle.h"

#include <cmath>
#include <random>
#include <vector>

#include "core/input_error.h"

namespace cosim {

namespace {

constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
constexpr int kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};

bool inBox(const TurningObstacleSpec& s, int x, int y) {
  return x >= s.box_min.x && x <= s.box_max.x && y >= s.box_min.y && y <= s.box_max.y;
}

// One step in direction d from c is legal: the target free and in the rectangle, and for a
// diagonal both side cells free.
bool stepAllowed(const OccupancyGrid& g, const TurningObstacleSpec& s, const Cell& c, int d) {
  const int x = c.x + kDx[d], y = c.y + kDy[d];
  if (!inBox(s, x, y) || g.blocked(x, y, 0)) return false;
  if (kDx[d] != 0 && kDy[d] != 0 && (g.blocked(c.x + kDx[d], c.y, 0) || g.blocked(c.x, y, 0)))
    return false;
  return true;
}

}  // namespace

MovingObstacle randomlyTurningObstacle(const OccupancyGrid& grid, const TurningObstacleSpec& spec,
                                       std::uint64_t seed) {
  Cell c = spec.start;
  if (!inBox(spec, c.x, c.y) || grid.blocked(c.x, c.y, 0))
    throw InputError("", "moving obstacle", "its start cell is blocked or outside its rectangle");
  std::mt19937_64 rng(seed);
  int d = ((spec.direction % 8) + 8) % 8;
  std::vector<Cell> turns = {c};
  double travelled = 0.0;
  while (travelled < spec.travel) {
    if (!stepAllowed(grid, spec, c, d)) {
      // A random new direction among the legal ones (uniform, drawn with the raw generator so the
      // sequence is the same on every standard library).
      int legal[8], n = 0;
      for (int k = 0; k < 8; ++k)
        if (stepAllowed(grid, spec, c, k)) legal[n++] = k;
      if (n == 0) throw InputError("", "moving obstacle", "boxed in: no free neighbour cell");
      d = legal[rng() % static_cast<std::uint64_t>(n)];
      if (turns.back() != c) turns.push_back(c);
    }
    c = {c.x + kDx[d], c.y + kDy[d], 0};
    travelled += (kDx[d] != 0 && kDy[d] != 0) ? std::sqrt(2.0) : 1.0;
  }
  turns.push_back(c);
  // Back and forth: past the end of its drawn route the obstacle retraces it, never jumps.
  return MovingObstacle(std::move(turns), spec.speed, MovingObstacle::Mode::BackAndForth);
}

}  // namespace cosim
