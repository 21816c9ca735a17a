#include "run/scenario_planning.h"

#include <algorithm>

#include "core/input_error.h"
#include "core/stop_token.h"
#include "planning/planner_registry.h"
#include "sim/world_model.h"

namespace cosim {

ParamSet plannerParameters(const PlannerSection& section, std::vector<std::string>* set_aside) {
  const PlannerEntry* entry = PlannerRegistry::instance().find(section.name);
  if (!section.name_from_override || !entry) return section.params;
  std::vector<std::string> own = {"time_limit"};  // read by planVehicle for every planner
  for (const ParamDeclaration& d : declaredParameters(*entry)) own.push_back(d.name);
  const std::vector<std::string>& any = allPlannerParameterNames();
  const auto listed = [](const std::vector<std::string>& list, const std::string& name) {
    return std::find(list.begin(), list.end(), name) != list.end();
  };
  std::vector<std::string> drop;
  for (const std::string& name : section.params.names())
    if (!listed(section.params_from_overrides, name) && !listed(own, name) && listed(any, name))
      drop.push_back(name);
  if (set_aside) set_aside->insert(set_aside->end(), drop.begin(), drop.end());
  return section.params.without(drop);
}

VehiclePlan planVehicle(const Scenario& scenario, const PlannerSection& section,
                        const VehicleSpec& vehicle, double vehicle_radius) {
  VehiclePlan plan;
  ParamSet params = plannerParameters(section, &plan.set_aside_params);
  plan.inflation = vehicle_radius + section.margin;
  if (section.name.empty()) {
    plan.success = true;
    plan.status = PlannerStatus::ExactSolution;
    plan.path.waypoints.push_back(vehicle.start);
    for (const auto& w : vehicle.waypoints) {
      plan.path.waypoints.push_back(w);
      plan.via_indices.push_back(plan.path.waypoints.size() - 1);
    }
    return plan;
  }
  const double time_limit = params.getDouble("time_limit", 30.0, 0.001, kMaxPlannerTimeLimit);
  auto planner = makePlanner(section.name, params, "key planner.name");
  plan.params = params.effective();
  plan.params["margin"] = std::to_string(section.margin);

  PlanningProblem problem;
  problem.world = &scenario.world;
  problem.inflation = plan.inflation;
  problem.planar = vehicle.kind == VehicleKind::GroundRobot;
  problem.seed = scenario.sim.seed;
  const StopToken deadline(time_limit);
  Eigen::Vector3d from = vehicle.start;
  plan.path.waypoints.push_back(from);
  for (std::size_t i = 0; i < vehicle.waypoints.size(); ++i) {
    problem.start = from;
    problem.goal = vehicle.waypoints[i];
    problem.time_limit_s = std::max(1e-3, time_limit - deadline.elapsedMs() / 1000.0);
    PlanResult r;
    try {
      r = planner->solve(problem, StopToken::untimed());
    } catch (const InputError& e) {
      throw e.inFile(scenario.file);  // e.g. the planner's grid is too large for the world
    }
    plan.time_ms += r.time_ms;
    for (const auto& [k, v] : r.counters) plan.counters[k] += v;
    if (!r.success || r.path.empty()) {
      plan.success = false;
      plan.status = r.status;
      plan.message = "no path from waypoint " + std::to_string(i) + " to " + std::to_string(i + 1) +
                     (r.message.empty() ? "" : ": " + r.message);
      return plan;
    }
    // Consecutive segments share their joining point.
    for (std::size_t k = 1; k < r.path.waypoints.size(); ++k)
      plan.path.waypoints.push_back(r.path.waypoints[k]);
    plan.via_indices.push_back(plan.path.waypoints.size() - 1);
    from = vehicle.waypoints[i];
  }
  plan.success = true;
  plan.status = PlannerStatus::ExactSolution;
  return plan;
}

VehiclePlan planVehicle(const Scenario& scenario, const VehicleSpec& vehicle, double vehicle_radius,
                        ParamSet planner_params) {
  PlannerSection section = scenario.motion.planner;
  section.params = std::move(planner_params);
  return planVehicle(scenario, section, vehicle, vehicle_radius);
}

VehiclePlan planFirstVehicle(const Scenario& scenario) {
  const WorldModel world = WorldModel::build(scenario);
  return planVehicle(scenario, scenario.motion.planner, scenario.vehicles.front(),
                     world.vehicles().front().params.radius);
}

}  // namespace cosim
