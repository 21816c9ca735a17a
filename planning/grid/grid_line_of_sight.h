#pragma once
// Line of sight between cell centres for the any-angle planners: the segment may touch no
// blocked cell, where "touch" includes passing exactly through a shared edge or corner
// (a supercover line, after E. Dedu's Bresenham-based supercover algorithm cited by seed 003,
// extended to 3D). A segment that grazes the corner between two diagonal blocked cells is
// therefore blocked, which agrees with the no-corner-cutting rule of the grid moves.
#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "planning/grid/occupancy_grid.h"

namespace cosim {

// Walks the cells the segment from the centre of a to the centre of b touches, in order, and
// returns false at the first cell for which blocked(x, y, z) is true. Exact integer arithmetic:
// the segment crosses the k-th boundary along axis i at parameter t = (2k + 1) / (2 |d_i|), and
// crossings at equal t (edges, corners) put every cell around that point on the line.
template <class BlockedFn>
bool supercoverLineOfSight(const Cell& a, const Cell& b, BlockedFn&& blocked) {
  const int d[3] = {std::abs(b.x - a.x), std::abs(b.y - a.y), std::abs(b.z - a.z)};
  const int s[3] = {b.x > a.x ? 1 : -1, b.y > a.y ? 1 : -1, b.z > a.z ? 1 : -1};
  // Crossing times scaled by the product of the non-zero |d_j| so that they compare as integers.
  std::int64_t scale[3];
  for (int i = 0; i < 3; ++i) {
    scale[i] = 1;
    for (int j = 0; j < 3; ++j)
      if (j != i && d[j] > 0) scale[i] *= d[j];
  }
  std::int64_t next[3];
  for (int i = 0; i < 3; ++i) next[i] = d[i] > 0 ? scale[i] : INT64_MAX;
  int c[3] = {a.x, a.y, a.z};
  if (blocked(c[0], c[1], c[2])) return false;
  int remaining = d[0] + d[1] + d[2];
  while (remaining > 0) {
    const std::int64_t t = std::min(next[0], std::min(next[1], next[2]));
    // Usually one axis crosses alone: step into the next cell.
    const int single = (next[0] == t) + (next[1] == t) + (next[2] == t) == 1 ? (next[0] == t   ? 0
                                                                                : next[1] == t ? 1
                                                                                               : 2)
                                                                             : -1;
    if (single >= 0) {
      c[single] += s[single];
      next[single] += 2 * scale[single];
      --remaining;
      if (blocked(c[0], c[1], c[2])) return false;
      continue;
    }
    int axes[3], n = 0;
    for (int i = 0; i < 3; ++i)
      if (next[i] == t) axes[n++] = i;
    // All cells c + (any non-empty subset of the crossing axes) touch the crossing point.
    for (int subset = 1; subset < (1 << n); ++subset) {
      int q[3] = {c[0], c[1], c[2]};
      for (int k = 0; k < n; ++k)
        if (subset & (1 << k)) q[axes[k]] += s[axes[k]];
      if (blocked(q[0], q[1], q[2])) return false;
    }
    for (int k = 0; k < n; ++k) {
      const int i = axes[k];
      c[i] += s[i];
      next[i] += 2 * scale[i];
      --remaining;
    }
  }
  return true;
}

// Cells outside the grid count as blocked.
inline bool gridLineOfSight(const OccupancyGrid& grid, const Cell& a, const Cell& b) {
  return supercoverLineOfSight(a, b, [&](int x, int y, int z) { return grid.blocked(x, y, z); });
}

}  // namespace cosim
