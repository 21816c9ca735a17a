#pragma once
// The environment of the configuration-space MAPF planners (LaCAM*, PIBT): a graph whose vertices
// are the free cells, each with its neighbours in a fixed order, and for every move the key of
// the space it sweeps. The planners know nothing else, so one implementation serves 2D grids
// (4- and 8-connected), 3D grids (6-, 18- and 26-connected) and any other graph a caller builds
// (as libMultiRobotPlanning keeps its searches generic over an environment).
//
// Moves that sweep the same space conflict: two agents moving at constant speed between cell
// centres are at the same point at the same time exactly when their moves have the same midpoint
// (a swap along an edge, two diagonals crossing in the middle of a 2x2 square or a 2x2x2 cube;
// with steps of at most one cell per axis a meeting can only happen at the half step). The key of
// a move is therefore its midpoint; the solution validator applies the same rule on its own.
#include <cstdint>
#include <span>
#include <vector>

#include "planning/grid/occupancy_grid.h"

namespace cosim {

class MapfGraph {
 public:
  static constexpr int kNoVertex = -1;

  // The free cells of `grid` and the moves `connectivity` allows: 4 or 8 on a 2D grid, 6, 18 or
  // 26 on a 3D one; a move that is not along one axis needs every cell of the box it spans free
  // (no corner cutting: seed 004 §4.2 and the MovingAI benchmarks). Throws InputError for any
  // other connectivity.
  static MapfGraph fromGrid(const OccupancyGrid& grid, int connectivity);

  int vertexCount() const { return static_cast<int>(cells_.size()); }
  int connectivity() const { return connectivity_; }
  // Largest number of neighbours of any vertex.
  int maxDegree() const { return max_degree_; }
  int degree(int v) const { return first_[v + 1] - first_[v]; }
  std::span<const int> neighbours(int v) const {
    return {targets_.data() + first_[v], targets_.data() + first_[v + 1]};
  }
  // moveKeys(v)[k] is the key of the move from v to neighbours(v)[k], in [0, moveKeyCount()).
  std::span<const std::uint32_t> moveKeys(int v) const {
    return {keys_.data() + first_[v], keys_.data() + first_[v + 1]};
  }
  std::uint32_t moveKeyCount() const { return key_count_; }

  // The vertex of a cell, kNoVertex if it is blocked or off the grid.
  int vertexOf(const Cell& c) const;
  const Cell& cellOf(int v) const { return cells_[v]; }

 private:
  int connectivity_ = 4;
  int max_degree_ = 0;
  int nx_ = 0, ny_ = 0, nz_ = 0;
  std::vector<Cell> cells_;           // vertex -> cell
  std::vector<int> vertex_of_index_;  // grid index -> vertex or kNoVertex
  std::vector<int> first_;            // CSR offsets into targets_ / keys_
  std::vector<int> targets_;
  std::vector<std::uint32_t> keys_;
  std::uint32_t key_count_ = 0;
};

}  // namespace cosim
