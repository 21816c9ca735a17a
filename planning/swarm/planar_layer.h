#pragma once
// Seed 002's grid planners (ant_grid, mmas, ga, pso) work on a plane. Given a 3D grid (a UAV
// scenario voxelised by GridWorldPlanner) they plan on the layer that contains the start, to the
// goal's column on that layer, and then climb or descend straight to the goal in that column;
// if that column is blocked the query fails with a message that says so.
#include <string>
#include <vector>

#include "planning/grid/grid_planner.h"

namespace cosim {

struct PlanarLayer {
  OccupancyGrid grid;       // one layer (nz = 1)
  Cell start, goal;         // on that layer (z = 0)
  int layer = 0;            // z of the layer in the query's grid
  std::vector<Cell> climb;  // cells after the layer's goal, up or down to the real goal
  std::string error;        // non-empty: the query cannot be planned (reason)
  PlannerStatus error_status = PlannerStatus::Unknown;  // with an error: InvalidStart or InvalidGoal
};

PlanarLayer planarLayerFor(const GridQuery& query);

// Turns a plan on the layer back into cells of the query's grid (and appends the climb).
std::vector<Cell> liftFromLayer(const std::vector<Cell>& cells, const PlanarLayer& layer);

}  // namespace cosim
