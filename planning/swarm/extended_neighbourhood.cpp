#include "planning/swarm/extended_neighbourhood.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace cosim {

namespace {
// Cells of the seed's neighbourhood table by ring: unit moves, then distance-2 straight and
// diagonal, knight moves, distance-3 straight and diagonal.
bool inNeighbourhood(int dx, int dy, int directions) {
  const int ax = std::abs(dx), ay = std::abs(dy);
  if (ax == 0 && ay == 0) return false;
  if (directions == 4) return ax + ay == 1;
  if (ax <= 1 && ay <= 1) return true;  // the 8 standard neighbours
  const bool straight_or_diagonal = ax == 0 || ay == 0 || ax == ay;
  if (directions >= 16 && ax <= 2 && ay <= 2 && straight_or_diagonal) return true;
  if (directions >= 24 && ax <= 2 && ay <= 2) return true;  // knight moves (1,2), (2,1)
  if (directions >= 32 && (ax == 3 || ay == 3) && straight_or_diagonal) return true;
  return false;
}
}  // namespace

ExtendedNeighbourhood::ExtendedNeighbourhood(int directions) {
  if (directions != 4 && directions != 8 && directions != 16 && directions != 24 &&
      directions != 32)
    throw std::invalid_argument("neighbourhood must have 4, 8, 16, 24 or 32 directions, not " +
                                std::to_string(directions));
  for (auto& row : index_) std::fill(std::begin(row), std::end(row), -1);
  for (int dy = -3; dy <= 3; ++dy)
    for (int dx = -3; dx <= 3; ++dx)
      if (inNeighbourhood(dx, dy, directions)) {
        index_[dy + 3][dx + 3] = static_cast<int>(offsets_.size());
        offsets_.push_back({dx, dy, std::hypot(dx, dy), std::atan2(dy, dx)});
      }
}

int ExtendedNeighbourhood::indexOf(int dx, int dy) const {
  if (std::abs(dx) > 3 || std::abs(dy) > 3) return -1;
  return index_[dy + 3][dx + 3];
}

bool ExtendedNeighbourhood::segmentClear(const OccupancyGrid& grid, const Cell& a, const Cell& b) {
  // Doubled integer coordinates: the centre of cell x is 2x + 1 and its closed square is
  // [2x, 2x + 2], so every test below is exact.
  const long px = 2L * a.x + 1, py = 2L * a.y + 1, qx = 2L * b.x + 1, qy = 2L * b.y + 1;
  const long ux = qx - px, uy = qy - py;
  for (int y = std::min(a.y, b.y); y <= std::max(a.y, b.y); ++y)
    for (int x = std::min(a.x, b.x); x <= std::max(a.x, b.x); ++x) {
      if (!grid.blocked(x, y, a.z)) continue;
      // The segment's bounding box always overlaps these cells' squares; the segment misses the
      // square only if all four corners lie strictly on one side of its line.
      int positive = 0, negative = 0;
      for (int corner = 0; corner < 4; ++corner) {
        const long cx = 2L * x + 2 * (corner & 1), cy = 2L * y + 2 * (corner >> 1);
        const long side = ux * (cy - py) - uy * (cx - px);
        positive += side > 0;
        negative += side < 0;
      }
      if (positive != 4 && negative != 4) return false;
    }
  return true;
}

bool ExtendedNeighbourhood::moveAllowed(const OccupancyGrid& grid, const Cell& c, int k) const {
  const NeighbourOffset& o = offsets_[k];
  const Cell t{c.x + o.dx, c.y + o.dy, c.z};
  if (grid.blocked(t)) return false;
  if (std::abs(o.dx) + std::abs(o.dy) == 1) return true;  // touches only c and t
  if (std::abs(o.dx) == 1 && std::abs(o.dy) == 1)         // a diagonal touches the two side cells
    return !grid.blocked(c.x + o.dx, c.y, c.z) && !grid.blocked(c.x, c.y + o.dy, c.z);
  return segmentClear(grid, c, t);
}

bool ExtendedNeighbourhood::legalMove(const OccupancyGrid& grid, const Cell& a,
                                      const Cell& b) const {
  if (a.z != b.z) return false;
  const int k = indexOf(b.x - a.x, b.y - a.y);
  return k >= 0 && moveAllowed(grid, a, k);
}

}  // namespace cosim
