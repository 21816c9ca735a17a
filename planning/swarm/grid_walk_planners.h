#pragma once
// Registers the planners of seed 002 and their swarm baselines: ant_grid, ga, mmas, pso (grid
// planners, 2D) and acs_maklink (continuous 2D, on a MAKLINK graph).
#include "planning/planner_registry.h"

namespace cosim {

void registerAnt002Planners(PlannerRegistry& r);

}  // namespace cosim
