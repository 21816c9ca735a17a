#pragma once
// Seed 004's maze generator (§4.1, Algorithm 4.1.1): a map of one-cell-wide corridors whose free
// cells are always connected. Every cell with both coordinates even starts free and unvisited;
// from a random first cell, each randomly picked unvisited cell is joined to its nearest visited
// cell (Manhattan distance; ties: the earliest visited) by a corridor carved along x first, then
// along y (WYBURZDROGĘ). Adding one joined cell at a time keeps the free cells one 4-connected
// component; no 2x2 block is ever free, so no diagonal move is possible (§4.1).
#include <cstdint>

#include "planning/grid/occupancy_grid.h"

namespace cosim {

// width, height >= 1 (any, not only odd or square: §5.1). Deterministic in seed.
OccupancyGrid generateMaze(int width, int height, std::uint64_t seed);

}  // namespace cosim
