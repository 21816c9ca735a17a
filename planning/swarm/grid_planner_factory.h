#pragma once
// The registry factory of the swarm grid planners (msac_saco_planners.cpp,
// grid_walk_planners.cpp): each planner's parameters are read by one named function
// (readMsacParams, readMmasParams, ...) and the factory builds the planner from what it returns.
#include <memory>

#include "planning/planner_registry.h"

namespace cosim {

// Planner(read(params, extra...)).
template <class Planner, class ReadParams, class... Extra>
GridPlannerFactory gridPlannerFactory(ReadParams read, Extra... extra) {
  return [read, extra...](ParamSet& params) -> std::unique_ptr<GridPlanner> {
    return std::make_unique<Planner>(read(params, extra...));
  };
}

}  // namespace cosim
