#pragma once
// What the ant planners of seed 000 (MSAC, SACO, SACOdm; Pěňčík 2014) share: the 2D grid they
// walk on, with the seed's two diagonal modes, and the path post-processing of §4.3.3 (cycle
// removal and light smoothing). Cells are flat indices y * nx + x for speed.
#include <array>
#include <optional>
#include <string>
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

// Seed 000 §4.3.3 path processing. `scratch` is a per-cell array that must hold -1 everywhere on
// entry; it is restored to -1 on exit (so a planner allocates it once per query).
class AntPathProcessing {
 public:
  explicit AntPathProcessing(const AntGridView& grid)
      : grid_(grid), position_(grid.cellCount(), -1) {}
  // Cuts every loop: when a cell recurs, everything between its two visits goes.
  void removeCycles(std::vector<int>& path);
  // Light smoothing: walking from the start, if a node has several later path nodes among its
  // legal neighbours, keep only the one with the highest index and drop the nodes in between.
  // Expects a loop-free path.
  void smoothLightly(std::vector<int>& path);
  // Wider-range smoothing, the extension the seed's author proposes (§6.1.4: [41]'s straight
  // path on scene 3 "would need smoothing over a wider range"): from each node, the farthest
  // node at most `range` path nodes ahead that a shortest obstacle-free 8-connected path reaches
  // (one of the two octile paths: diagonal run then straight run, or straight then diagonal)
  // replaces the nodes in between when it is shorter.
  void smoothWide(std::vector<int>& path, int range);

 private:
  // Appends to `out` the cells after a on an octile path to b (diagonal run first if
  // diagonal_first); false, leaving `out` as it was, if a cell or move is blocked.
  bool octilePath(int a, int b, bool diagonal_first, std::vector<int>& out) const;

  const AntGridView& grid_;
  std::vector<int> position_;  // index of a cell in the path being processed, or -1
};

}  // namespace cosim
