#pragma once
// The local search of the memetic variants (mmas by default; ant_grid and ga on request): a grid
// analogue of 2-opt. Any piece of the path of at most `window` moves whose endpoints could be
// joined more cheaply by a straight-then-diagonal or diagonal-then-straight staircase (4
// directions: x-then-y or y-then-x) is replaced by that staircase when it is free. Each
// replacement strictly shortens the path, so the search ends; it repeats until no piece
// improves. Staircases use unit moves only, which every neighbourhood of seed 002 contains.
#include <cstdint>
#include <vector>

#include "planning/swarm/extended_neighbourhood.h"

namespace cosim {

class PathShortcut {
 public:
  // Builds a summed-area table of the blocked cells of layer 0 (O(cells)), so that straight runs
  // and obstacle-free rectangles are tested in constant time.
  PathShortcut(const OccupancyGrid& grid, const ExtendedNeighbourhood& moves);

  // Returns the number of replacements made. cells must be a legal path of `moves` on layer 0;
  // it stays one.
  int improve(std::vector<Cell>& cells, int window = 48) const;

 private:
  // Blocked cells in the rectangle [x0, x1] x [y0, y1] (inclusive, any corner order).
  std::int64_t blockedIn(int x0, int y0, int x1, int y1) const;
  // Appends the cells after a of a staircase to b; false if a move of it is not allowed.
  bool staircase(const Cell& a, const Cell& b, bool diagonal_first, std::vector<Cell>& out) const;

  const OccupancyGrid& grid_;
  bool diagonals_;
  std::vector<std::int64_t> sum_;  // (nx + 1) * (ny + 1) prefix sums
};

}  // namespace cosim
