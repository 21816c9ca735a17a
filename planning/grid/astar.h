#pragma once
// A* on an occupancy grid (Hart, Nilsson & Raphael 1968; seed 003 Alg. 3, seed 004 Alg. 4.2.1):
// f = g + w h with the exact obstacle-free distance of the move set as h (octile for 8/26
// moves, Manhattan for 4/6), which is consistent, so the path is optimal for w = 1.
#include <string>

#include "planning/grid/grid_best_first_search.h"
#include "planning/grid/grid_planner.h"

namespace cosim {

struct AStarOptions {
  GridMoves moves{0, false};      // connectivity 0: all moves (8 in 2D, 26 in 3D)
  double heuristic_weight = 1.0;  // > 1: weighted A*, faster, at most w times longer
};

class AStar : public GridPlanner {
 public:
  using Options = AStarOptions;
  // params_file names where the options came from, for errors found at solve time.
  explicit AStar(const Options& options = {}, std::string params_file = "")
      : options_(options), params_file_(std::move(params_file)) {}

  std::string name() const override { return "astar"; }
  GridPlanResult solveGrid(const GridQuery& query, const StopToken& stop) override;
  bool checksSegments() const override { return true; }

 private:
  Options options_;
  std::string params_file_;
  BestFirstWorkspace work_;  // reused across queries (generation counters, no clearing)
};

// One optimal A* query, for callers that need a reference path or an optimality gap.
GridPlanResult planAStar(const OccupancyGrid& grid, const Cell& start, const Cell& goal,
                         const GridMoves& moves = {0, false}, double time_limit_s = 10.0);

}  // namespace cosim
