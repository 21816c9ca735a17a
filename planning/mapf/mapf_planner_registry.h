#pragma once
// The multi-agent planners by name (independent_astar, lra_star, ca_star, hca_star,
// whca_star, cbs, potential_field, lacam, pibt), separate from the single-agent PlannerRegistry
// because they solve a different problem (a MapfInstance, not a PlanningProblem). Parameters
// come by name from a ParamSet, as for every planner; unknown or misspelt ones are an
// InputError.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "planning/mapf/mapf_planner.h"
#include "core/param_set.h"

namespace cosim {

using MapfPlannerFactory = std::function<std::unique_ptr<MapfPlanner>(ParamSet& params)>;

struct MapfPlannerEntry {
  std::string name;
  std::string summary;
  MapfPlannerFactory make;
};

const std::vector<MapfPlannerEntry>& mapfPlanners();

// Whether `name` is one of mapfPlanners().
bool isMapfPlanner(const std::string& name);

// The parameters `entry`'s planner reads, as declared when it is built from an empty set.
std::vector<ParamDeclaration> declaredParameters(const MapfPlannerEntry& entry);

// Throws InputError for an unknown name (place names where it came from, e.g. "--planner") or
// unknown/invalid parameters.
std::unique_ptr<MapfPlanner> makeMapfPlanner(const std::string& name, ParamSet& params,
                                             const std::string& place = "--planner");

}  // namespace cosim
