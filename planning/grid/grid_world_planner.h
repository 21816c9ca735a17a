#pragma once
// Adapts a GridPlanner to a world: voxelises the scenario's obstacles (grown by the vehicle's
// inflation) at `resolution` metres, plans between the cells of start and goal, and returns a
// metric path from the exact start through the cell centres to the exact goal (the start's and the
// goal's own cell centres left out where the straight segment past them is clear). With
// Blocking::Exact (the default of the planners that support it) a cell is free iff the vehicle
// can stand at its centre and every edge is checked against the inflated obstacles
// (GridSegmentChecker); Blocking::AnyPoint blocks a cell when any point of it is near an
// obstacle; Blocking::Centre is seed 003's rule (only when its centre is, edges unchecked).
// A failure says why (grid_passage_diagnosis.h).
#include <memory>

#include "planning/grid/grid_planner.h"
#include "planning/planner.h"

namespace cosim {

class GridWorldPlanner : public Planner {
 public:
  GridWorldPlanner(std::unique_ptr<GridPlanner> planner, double resolution,
                   OccupancyGrid::Blocking blocking = OccupancyGrid::Blocking::AnyPoint)
      : planner_(std::move(planner)), resolution_(resolution), blocking_(blocking) {}
  std::string name() const override { return planner_->name(); }
  PlanResult solve(const PlanningProblem& problem, const StopToken& stop) override;

 private:
  std::unique_ptr<GridPlanner> planner_;
  double resolution_;
  OccupancyGrid::Blocking blocking_;
};

}  // namespace cosim
