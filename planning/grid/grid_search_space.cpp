#include "planning/grid/grid_search_space.h"

#include <cstdlib>

#include "planning/grid/grid_line_of_sight.h"
#include "core/input_error.h"

namespace cosim {

GridMoves resolveGridMoves(const GridMoves& moves, bool three_d, const std::string& file) {
  GridMoves r = moves;
  const int c = moves.connectivity;
  if (c == 0) {
    r.connectivity = three_d ? 26 : 8;
    return r;
  }
  const bool fits = three_d ? (c == 6 || c == 18 || c == 26) : (c == 4 || c == 8);
  if (!fits)
    throw InputError(file, "parameter connectivity",
                     std::to_string(c) + " does not apply to a " + (three_d ? "3D" : "2D") +
                         " grid (use " + (three_d ? "6, 18 or 26" : "4 or 8") +
                         ", or 0 for all moves)");
  return r;
}

GridSearchSpace::GridSearchSpace(const OccupancyGrid& grid, const GridMoves& moves,
                                 const GridSegmentChecker* segments)
    : grid_(&grid),
      segments_(segments),
      cells_(grid.data()),
      nx_(grid.nx()),
      ny_(grid.ny()),
      nz_(grid.nz()) {
  // Every neighbour a move can need gets one bit; a move needs the cells of the unit box it
  // spans (other than its origin) when corner cutting is off, else only its target.
  const std::int64_t plane = static_cast<std::int64_t>(nx_) * ny_;
  auto bitOf = [&](int dx, int dy, int dz) {
    const std::int64_t off = dz * plane + static_cast<std::int64_t>(dy) * nx_ + dx;
    for (std::size_t k = 0; k < probes_.size(); ++k)
      if (probes_[k].offset == off) return static_cast<std::uint32_t>(1) << k;
    probes_.push_back({off, dx, dy, dz});
    return static_cast<std::uint32_t>(1) << (probes_.size() - 1);
  };
  const FixedCost fixed[4] = {0, kFixedStraight, kFixedFaceDiagonal, kFixedBodyDiagonal};
  for (const GridStep& s : gridSteps(moves, grid.is3D())) {
    const int order = std::abs(s.dx) + std::abs(s.dy) + std::abs(s.dz);
    Move m{s.dz * plane + static_cast<std::int64_t>(s.dy) * nx_ + s.dx,
           s.dx,
           s.dy,
           s.dz,
           s.cost,
           fixed[order],
           bitOf(s.dx, s.dy, s.dz),
           {},
           0};
    for (int mz = 0; mz <= std::abs(s.dz); ++mz)
      for (int my = 0; my <= std::abs(s.dy); ++my)
        for (int mx = 0; mx <= std::abs(s.dx); ++mx) {
          if (mx + my + mz == 0) continue;
          m.box[m.box_cells++] =
              mz * s.dz * plane + static_cast<std::int64_t>(my * s.dy) * nx_ + mx * s.dx;
          if (!moves.corner_cutting) m.need |= bitOf(mx * s.dx, my * s.dy, mz * s.dz);
        }
    moves_.push_back(m);
  }
}

bool GridSearchSpace::lineOfSight(std::uint32_t a, std::uint32_t b) const {
  // The walk stays in the bounding box of two grid cells, so raw indexing is safe.
  const std::int64_t plane = static_cast<std::int64_t>(nx_) * ny_;
  const Cell ca = cellOf(a), cb = cellOf(b);
  if (segments_ == nullptr)
    return supercoverLineOfSight(ca, cb, [this, plane](int x, int y, int z) {
      return cells_[z * plane + static_cast<std::int64_t>(y) * nx_ + x] != 0;
    });
  // One walk finds both blocked cells and cells near an obstacle; only a line passing near one
  // needs the exact test.
  const std::uint8_t* near = segments_->nearData();
  bool touches_near = false;
  const bool sees = supercoverLineOfSight(ca, cb, [&](int x, int y, int z) {
    const std::int64_t i = z * plane + static_cast<std::int64_t>(y) * nx_ + x;
    touches_near |= near[i] != 0;
    return cells_[i] != 0;
  });
  return sees &&
         (!touches_near || segments_->pointsClear(grid_->cellCenter(ca), grid_->cellCenter(cb)));
}

}  // namespace cosim
