#pragma once
// Adapts a GridPlanner to a world: voxelises the scenario's obstacles (grown by the vehicle's
// inflation) at `resolution` metres, plans between the cells of start and goal, and returns a
// metric path from the exact start through the cell centres to the exact goal.
#include <memory>

#include "planning/grid/grid_planner.h"
#include "planning/planner.h"

namespace cosim {

class GridWorldPlanner : public Planner {
 public:
  GridWorldPlanner(std::unique_ptr<GridPlanner> planner, double resolution)
      : planner_(std::move(planner)), resolution_(resolution) {}
  std::string name() const override { return planner_->name(); }
  PlanResult solve(const PlanningProblem& problem) override;

 private:
  std::unique_ptr<GridPlanner> planner_;
  double resolution_;
};

}  // namespace cosim
