#pragma once
// Registers the navigators by their scenario names: rna and wf_rna (seed 000's Robot Navigation
// Ant, re-planning with MSAC or a wave front) and d_star_lite. Each is registered as a grid
// planner that drives through a static map seen only through the robot's field of view.
#include "planning/planner_registry.h"

namespace cosim {

void registerNavigationPlanners(PlannerRegistry& r);

}  // namespace cosim
