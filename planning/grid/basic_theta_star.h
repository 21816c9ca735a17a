#pragma once
// Basic Theta* (Nash, Daniel, Koenig & Felner, AAAI 2007; seed 003 Alg. 4): A* whose
// relaxation makes a neighbour's parent the expanded cell's own parent whenever the two see each
// other (supercover line of sight), giving any-angle paths through cell centres. Heuristic:
// straight-line distance. Never longer than A* on the same moves: every relaxation offers a cost
// no larger than A*'s (triangle inequality), so the Dijkstra argument bounds g(goal) by A*'s.
#include <string>

#include "planning/grid/grid_any_angle_search.h"
#include "planning/grid/grid_planner.h"

namespace cosim {

class BasicThetaStar : public GridPlanner {
 public:
  explicit BasicThetaStar(const GridMoves& moves = {0, false}, std::string params_file = "")
      : moves_(moves), params_file_(std::move(params_file)) {}

  std::string name() const override { return "theta_star"; }
  GridPlanResult solveGrid(const GridQuery& query, const StopToken& stop) override;
  bool checksSegments() const override { return true; }

 private:
  GridMoves moves_;
  std::string params_file_;
  AnyAngleWorkspace work_;  // reused across queries
};

}  // namespace cosim
