#pragma once
// Registers the walk-based grid planners by their scenario names: ant_grid (seed 002's grid ant
// algorithm) and the swarm baselines it is compared with, mmas, ga and pso. All four build their
// paths as GridWalk walks over an ExtendedNeighbourhood of 4 to 32 directions, on the start's
// layer. (acs_maklink, seed 002's other planner, plans in the plane: acs_maklink.h.)
#include "planning/planner_registry.h"

namespace cosim {

void registerGridWalkPlanners(PlannerRegistry& r);

}  // namespace cosim
