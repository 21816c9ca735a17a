#pragma once
// The grid environment the MAPF searches run on: cells as dense ids, the legal moves of each
// free cell (precomputed once), the spatial heuristic, and the key of the space a move sweeps.
// The search algorithms know nothing else about the grid.
#include <cstdint>
#include <span>
#include <vector>

#include "planning/grid/occupancy_grid.h"
#include "planning/mapf/mapf_problem.h"

namespace cosim {

class MapfGrid {
 public:
  // connectivity 4 or 8; with 8 a diagonal move needs both side cells free (seed 004 §4.2,
  // PRZEJŚCIEPOPRAWNE), so a robot never clips a wall corner.
  MapfGrid(const OccupancyGrid& grid, int connectivity);

  int width() const { return nx_; }
  int height() const { return ny_; }
  int cellCount() const { return nx_ * ny_; }
  int connectivity() const { return connectivity_; }
  int id(const Cell& c) const { return c.y * nx_ + c.x; }
  Cell cell(int id) const { return {id % nx_, id / nx_, 0}; }
  bool free(int id) const { return free_[id] != 0; }
  MapfPath toCells(const std::vector<int>& ids) const {
    MapfPath cells;
    cells.reserve(ids.size());
    for (const int i : ids) cells.push_back(cell(i));
    return cells;
  }

  // Free cells reachable in one move (waiting not included), in a fixed order.
  std::span<const int> neighbours(int id) const {
    return {moves_.data() + first_move_[id], moves_.data() + first_move_[id + 1]};
  }

  // Admissible and consistent lower bound on the number of steps from a to b ignoring obstacles:
  // Manhattan distance on 4-connected grids, Chebyshev distance on 8-connected ones (a diagonal
  // move costs one step like any other, seed 004 §3.6).
  int lowerBound(int a, int b) const;

  // Two agents moving in the same time step collide exactly when their moves sweep the same
  // space: the same edge (a swap) or, for diagonal moves, the same 2x2 block (a swap along the
  // diagonal, or two diagonals crossing at the block centre). This returns that space's key;
  // moves from different cells with equal keys conflict. Waiting sweeps nothing.
  std::uint32_t moveKey(int from, int to) const;
  static constexpr std::uint32_t kNoMove = 0xffffffffu;

 private:
  int nx_, ny_, connectivity_;
  std::vector<std::uint8_t> free_;
  std::vector<int> first_move_;  // CSR offsets into moves_
  std::vector<int> moves_;
};

}  // namespace cosim
