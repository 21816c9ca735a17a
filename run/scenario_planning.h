#pragma once
// Turns a scenario's vehicle into a path: through the planner the scenario names (segment by
// segment: start -> waypoint 1 -> ... -> goal), or the given waypoints when there is none.
#include <map>
#include <string>
#include <vector>

#include "planning/path.h"
#include "planning/planner_status.h"
#include "sim/motion_sections.h"
#include "sim/scenario.h"

namespace cosim {

// The largest planner.time_limit (s) a scenario may ask for: an hour. More is surely a mistake
// (a day was allowed), and SIGINT/SIGTERM stop a planner at any time anyway.
constexpr double kMaxPlannerTimeLimit = 3600.0;

struct VehiclePlan {
  bool success = false;
  Path path;
  double time_ms = 0.0;
  std::map<std::string, double> counters;     // summed over segments
  std::map<std::string, std::string> params;  // the planner's parameters in force
  std::string message;
  PlannerStatus status = PlannerStatus::Unknown;  // the failing segment's, else ExactSolution
  double inflation = 0.0;                         // vehicle radius + margin the planner kept clear
  std::map<std::string, double> trajectory_counters;  // from the minimum-snap fit, if any
  std::vector<std::string> ignored_params;            // taken by other planners, not by this one
  // Indices in `path` of the vehicle's waypoints (the points it was asked to visit, the goal
  // last): a trajectory through the path must not cut past them.
  std::vector<std::size_t> via_indices;
  // When the vehicle is due at each point of `path` (s): a ground robot's timed plan. Empty for
  // a path without times (a quadrotor's reference is timed by its trajectory).
  std::vector<double> point_times;
};

// `vehicle` planned in the scenario's world by `planner` (its name, parameters and margin);
// `vehicle_radius` comes from the model. Throws InputError for an unknown planner or bad
// parameters.
VehiclePlan planVehicle(const Scenario& scenario, const PlannerSection& planner,
                        const VehicleSpec& vehicle, double vehicle_radius);
// The same with the scenario's top-level planner and `planner_params` in place of its own
// (a benchmark's parameters).
VehiclePlan planVehicle(const Scenario& scenario, const VehicleSpec& vehicle, double vehicle_radius,
                        ParamSet planner_params);

// The first vehicle's plan in the scenario's world (`cosim plan`, Python's cosim.plan), its size
// from its model (the world is composed to read it).
VehiclePlan planFirstVehicle(const Scenario& scenario);

}  // namespace cosim
