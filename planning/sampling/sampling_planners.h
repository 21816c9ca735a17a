#pragma once
// Registers the continuous sampling planners: prm, rrt, rrt_star, rrt_star_thesis, rrt_star_fn,
// rrt_connect, informed_rrt_star.
#include "planning/planner_registry.h"

namespace cosim {

void registerSamplingPlanners(PlannerRegistry& r);

}  // namespace cosim
