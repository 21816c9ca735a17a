#pragma once
// The registry factories of the swarm and navigation grid planners (planners_000.cpp,
// planners_002.cpp): each planner's parameters are read by one named function (readMsacParams,
// readMmasParams, ...) and the factory builds the planner from what it returns.
#include <memory>
#include <string>

#include "planning/navigation/navigator_grid_planner.h"
#include "planning/planner_registry.h"

namespace cosim {

// Planner(read(params, extra...)).
template <class Planner, class ReadParams, class... Extra>
GridPlannerFactory gridPlannerFactory(ReadParams read, Extra... extra) {
  return [read, extra...](ParamSet& params) -> std::unique_ptr<GridPlanner> {
    return std::make_unique<Planner>(read(params, extra...));
  };
}

// A NavigatorGridPlanner named `name` whose robot is Navigator(read(params, extra...)).
template <class Navigator, class ReadParams, class... Extra>
GridPlannerFactory navigatorFactory(const std::string& name, ReadParams read, Extra... extra) {
  return [name, read, extra...](ParamSet& params) -> std::unique_ptr<GridPlanner> {
    const auto p = read(params, extra...);
    return std::make_unique<NavigatorGridPlanner>(name,
                                                  [p] { return std::make_unique<Navigator>(p); });
  };
}

}  // namespace cosim
