#pragma once
// Dijkstra's algorithm on an occupancy grid (Dijkstra 1959; seed 003 Alg. 1 after Cormen): the
// best-first loop of A* without a heuristic, stopping when the goal is taken from OPEN. Used as
// the uninformed reference: same optimal lengths as A*, more expansions.
#include <string>

#include "planning/grid/grid_best_first_search.h"
#include "planning/grid/grid_planner.h"

namespace cosim {

class Dijkstra : public GridPlanner {
 public:
  explicit Dijkstra(const GridMoves& moves = {0, false}, std::string params_file = "")
      : moves_(moves), params_file_(std::move(params_file)) {}

  std::string name() const override { return "dijkstra"; }
  GridPlanResult solveGrid(const GridQuery& query, const StopToken& stop) override;
  bool checksSegments() const override { return true; }

 private:
  GridMoves moves_;
  std::string params_file_;
  BestFirstWorkspace work_;
};

}  // namespace cosim
