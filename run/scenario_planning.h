#pragma once
// Turns a scenario's vehicle into a path: through the planner the scenario names (segment by
// segment: start -> waypoint 1 -> ... -> goal), or the given waypoints when there is none.
#include <map>
#include <string>
#include <vector>

#include "run/record/vehicle_plan.h"
#include "sim/motion_sections.h"
#include "sim/scenario.h"

namespace cosim {

// The largest planner.time_limit (s) a scenario may ask for: an hour. More is surely a mistake
// (a day was allowed), and SIGINT/SIGTERM stop a planner at any time anyway.
constexpr double kMaxPlannerTimeLimit = 3600.0;

// The parameters `section`'s planner is built from. Where the planner was chosen by an override
// (`cosim plan forest.yaml --planner rrt_star`, a sweep varying planner.name, Python's planner=)
// the file's parameters of other planners (the forest's grid `resolution`) are set aside, their
// names added to `set_aside` if given: the file was written for its own planner. Anything else
// stays, so a parameter the chosen planner does not take is refused when it is built (a
// `--set planner.step=1` with theta_star).
ParamSet plannerParameters(const PlannerSection& section,
                           std::vector<std::string>* set_aside = nullptr);

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
