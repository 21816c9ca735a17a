#include "planning/mapf/mapf_grid.h"

#include <algorithm>
#include <cstdlib>

#include "planning/grid/grid_planner.h"
#include "core/input_error.h"

namespace cosim {

MapfGrid::MapfGrid(const OccupancyGrid& grid, int connectivity)
    : nx_(grid.nx()), ny_(grid.ny()), connectivity_(connectivity) {
  if (grid.is3D())
    throw InputError("", "map", "this planner needs a 2D map (lacam and pibt plan on 3D grids)");
  if (connectivity != 4 && connectivity != 8)
    throw InputError("", "connectivity", "MAPF grids are 4- or 8-connected");
  const GridMoves rules{connectivity, /*corner_cutting=*/false};
  const auto steps = gridSteps(rules, false);
  free_.resize(cellCount());
  first_move_.reserve(cellCount() + 1);
  for (int id = 0; id < cellCount(); ++id) {
    const Cell c = cell(id);
    free_[id] = grid.free(c) ? 1 : 0;
    first_move_.push_back(static_cast<int>(moves_.size()));
    if (!free_[id]) continue;
    for (const auto& s : steps)
      if (gridStepAllowed(grid, c, s, false)) moves_.push_back(id + s.dy * nx_ + s.dx);
  }
  first_move_.push_back(static_cast<int>(moves_.size()));
}

int MapfGrid::lowerBound(int a, int b) const {
  const int dx = std::abs(a % nx_ - b % nx_), dy = std::abs(a / nx_ - b / nx_);
  return connectivity_ == 4 ? dx + dy : std::max(dx, dy);
}

std::uint32_t MapfGrid::moveKey(int from, int to) const {
  if (from == to) return kNoMove;
  const int fx = from % nx_, fy = from / nx_, tx = to % nx_, ty = to / nx_;
  // The key is 4 * (the top-left cell of the swept edge or block) + the kind of move.
  const auto key = [this](int x, int y, std::uint32_t kind) {
    return static_cast<std::uint32_t>(y * nx_ + x) * 4u + kind;
  };
  if (fy == ty) return key(std::min(fx, tx), fy, 0u);  // horizontal edge
  if (fx == tx) return key(fx, std::min(fy, ty), 1u);  // vertical edge
  return key(std::min(fx, tx), std::min(fy, ty), 2u);  // diagonal: the 2x2 block
}

}  // namespace cosim
