#include "planning/grid/grid_planner.h"

#include <cmath>
#include <cstdlib>

namespace cosim {

std::vector<GridStep> gridSteps(const GridMoves& moves, bool three_d) {
  std::vector<GridStep> steps;
  const int zr = three_d ? 1 : 0;
  for (int dz = -zr; dz <= zr; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int order = std::abs(dx) + std::abs(dy) + std::abs(dz);
        if (order == 0) continue;
        const bool axis_only = moves.connectivity == 4 || moves.connectivity == 6;
        if (axis_only && order > 1) continue;
        if (moves.connectivity == 18 && order > 2) continue;
        steps.push_back({dx, dy, dz, std::sqrt(static_cast<double>(order))});
      }
  return steps;
}

bool gridStepAllowed(const OccupancyGrid& grid, const Cell& c, const GridStep& s,
                     bool corner_cutting) {
  const Cell t{c.x + s.dx, c.y + s.dy, c.z + s.dz};
  if (grid.blocked(t)) return false;
  if (corner_cutting || std::abs(s.dx) + std::abs(s.dy) + std::abs(s.dz) < 2) return true;
  // Every cell of the unit box spanned by the move (other than c and t) must be free.
  for (int mz = 0; mz <= std::abs(s.dz); ++mz)
    for (int my = 0; my <= std::abs(s.dy); ++my)
      for (int mx = 0; mx <= std::abs(s.dx); ++mx) {
        const Cell side{c.x + mx * s.dx, c.y + my * s.dy, c.z + mz * s.dz};
        if (side != c && side != t && grid.blocked(side)) return false;
      }
  return true;
}

double gridPathLength(const std::vector<Cell>& cells) {
  double total = 0.0;
  for (std::size_t i = 1; i < cells.size(); ++i) {
    const double dx = cells[i].x - cells[i - 1].x, dy = cells[i].y - cells[i - 1].y,
                 dz = cells[i].z - cells[i - 1].z;
    total += std::sqrt(dx * dx + dy * dy + dz * dz);
  }
  return total;
}

}  // namespace cosim
