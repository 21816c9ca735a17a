#pragma once
// The grid planner family: dijkstra, bellman_ford, astar, theta_star, lazy_theta_star.
// Parameters (all planners): connectivity (0 = all moves, i.e. 8 in 2D and 26 in 3D; or 4/8 in
// 2D, 6/18/26 in 3D), corner_cutting (false: a diagonal move needs the cells it sweeps past
// free, as in seed 004 and the MovingAI benchmarks). astar also takes heuristic_weight (1).
#include "planning/grid/grid_planner.h"
#include "core/param_set.h"

namespace cosim {

class PlannerRegistry;

void registerGridPlanners(PlannerRegistry& registry);

// Reads connectivity and corner_cutting from params (throws InputError for invalid values).
GridMoves readGridMoves(ParamSet& params);

}  // namespace cosim
