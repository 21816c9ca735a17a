#pragma once
// The 2D grid the ant planners of seed 000 (MSAC, SACO, SACOdm, and RNA through MSAC; Pěňčík
// 2014) walk on, with the seed's two diagonal modes. Cells are flat indices y * nx + x for speed.
// Their path post-processing is ant_path_processing.h.
#include <array>
#include <optional>
#include <vector>

#include "planning/grid/grid_planner.h"

namespace cosim {

// A 2D view of an OccupancyGrid for the ant planners. They operate in 2D, as the seed does: on a
// 3D grid (a UAV scenario voxelised by GridWorldPlanner) they search the layer that holds both
// start and goal; start and goal on different layers is an error ("2D planner ...").
class AntGridView {
 public:
  // conditional_diagonal: a diagonal step needs both orthogonal side cells free (the seed's
  // "podmíněný diagonální pohyb", original MSAC); false: only the target cell must be free.
  AntGridView(const OccupancyGrid& grid, int layer, bool conditional_diagonal);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int cellCount() const { return nx_ * ny_; }
  int layer() const { return layer_; }
  int index(int x, int y) const { return y * nx_ + x; }
  int x(int i) const { return i % nx_; }
  int y(int i) const { return i / nx_; }
  bool blocked(int i) const { return blocked_[i] != 0; }
  Cell cell(int i) const { return {x(i), y(i), layer_}; }
  int index(const Cell& c) const { return index(c.x, c.y); }

  // Legal moves from cell i on the static map, in a fixed order (E, NE, N, ... around the
  // compass); returns how many were written to out.
  int neighbours(int i, std::array<int, 8>& out) const;
  // True if b is one of the legal moves from a.
  bool adjacent(int a, int b) const;
  double stepLength(int a, int b) const { return (x(a) != x(b) && y(a) != y(b)) ? kSqrt2 : 1.0; }
  double distance(int a, int b) const;  // Euclidean, in cells
  double pathLength(const std::vector<int>& path) const;
  std::vector<Cell> toCells(const std::vector<int>& path) const;

  static constexpr double kSqrt2 = 1.4142135623730951;

 private:
  int nx_ = 0, ny_ = 0, layer_ = 0;
  bool conditional_diagonal_ = true;
  std::vector<unsigned char> blocked_;
};

// The common start of an ant planner's query: start and goal on one layer, neither blocked, and
// the trivial query start == goal. Returns the grid to search, or nullopt when `result` is
// already final (a failure with its message, or the one-cell path).
std::optional<AntGridView> antGridForQuery(const GridQuery& query, bool conditional_diagonal,
                                           GridPlanResult& result);

}  // namespace cosim
