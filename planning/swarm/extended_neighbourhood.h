#pragma once
// The move sets of seed 002's grid ants (summary sections 1.3 and 2.3): 4 and 8 directions, and
// the "more degrees of freedom" neighbourhoods of 16 (adds the straight and diagonal cells at
// distance 2), 24 (adds the knight-move cells) and 32 (adds the straight and diagonal cells at
// distance 3; the seed's text says "30" but lists 32 cells).
//
// A long move is legal when its target is free and the segment between the two cell centres
// touches no blocked cell: every cell whose closed square meets the segment must be free. For
// the 8 unit moves this is exactly the no-corner-cutting rule of GridMoves (a diagonal passes
// through the corner shared with both side cells), so 8-direction paths are comparable with the
// MovingAI optimal lengths.
#include <vector>

#include "planning/grid/occupancy_grid.h"

namespace cosim {

struct NeighbourOffset {
  int dx = 0, dy = 0;
  double length = 0.0;  // Euclidean, in cells
  double angle = 0.0;   // atan2(dy, dx), radians
};

class ExtendedNeighbourhood {
 public:
  // directions: 4, 8, 16, 24 or 32; anything else throws std::invalid_argument.
  explicit ExtendedNeighbourhood(int directions);

  int directions() const { return static_cast<int>(offsets_.size()); }
  const std::vector<NeighbourOffset>& offsets() const { return offsets_; }
  const NeighbourOffset& offset(int k) const { return offsets_[k]; }
  // Index of the move (dx, dy), or -1 if it is not in this neighbourhood.
  int indexOf(int dx, int dy) const;

  // Move k from cell c (on layer c.z) is legal: target inside and free, and the segment between
  // the centres touches no blocked cell.
  bool moveAllowed(const OccupancyGrid& grid, const Cell& c, int k) const;
  // Same test for an arbitrary pair of cells on one layer (any offset).
  static bool segmentClear(const OccupancyGrid& grid, const Cell& a, const Cell& b);
  // a -> b is a legal single move of this neighbourhood.
  bool legalMove(const OccupancyGrid& grid, const Cell& a, const Cell& b) const;

 private:
  std::vector<NeighbourOffset> offsets_;
  int index_[7][7];  // indexOf table for |dx|, |dy| <= 3
};

}  // namespace cosim
