#pragma once
// A heuristic for a search towards one fixed goal cell: the number of steps still needed.
#include "planning/mapf/mapf_grid.h"

namespace cosim {

class GoalDistance {
 public:
  static constexpr int kUnreachable = 1 << 29;
  virtual ~GoalDistance() = default;
  virtual int distance(int cell) = 0;
};

// Manhattan (4-connected) or Chebyshev (8-connected) distance, ignoring obstacles: the plain
// spatial heuristic of Cooperative A* (Silver 2005, §3; seed 004 eqs. 3.4-3.5).
class GridLowerBoundDistance final : public GoalDistance {
 public:
  GridLowerBoundDistance(const MapfGrid& grid, int goal) : grid_(&grid), goal_(goal) {}
  int distance(int cell) override { return grid_->lowerBound(cell, goal_); }

 private:
  const MapfGrid* grid_;
  int goal_;
};

}  // namespace cosim
