#include "run/quadrotor_pilots.h"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "control/waypoint_reference.h"
#include "run/quadrotor_team_planning.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/trajectory/minimum_snap_trajectory.h"
#include "sim/controller_factory.h"
#include "sim/model_error.h"
#include "sim/trajectory_reference.h"

namespace cosim {

namespace {

// A minimum-snap trajectory through the planned path, within the airframe's limits: speed and
// acceleration from the scenario's trajectory section, thrust from the model (keeping 20 % of
// the rotors' thrust for control).
MinimumSnapResult fitMinimumSnap(const Scenario& s, const VehicleSpec& spec,
                                 const QuadrotorParams& q, const VehiclePlan& plan, ParamSet& p) {
  MinimumSnapOptions o;
  o.limits.max_speed = p.getDouble("max_speed", 3.0, 0.01, 100.0);
  o.limits.max_acceleration = p.getDouble("max_acceleration", 3.0, 0.01, 100.0);
  o.limits.gravity = q.gravity;
  if (!spec.ground) o.limits.max_thrust_accel = 0.8 * 4.0 * q.max_thrust / q.mass;
  o.time_penalty = p.getDouble("k_t", o.time_penalty, 0.0, 1e9);
  o.optimize_times = p.getBool("optimize_times", o.optimize_times);
  o.shortcut = p.getBool("shortcut", o.shortcut);
  o.max_repair_rounds = p.getInt("max_repair_rounds", o.max_repair_rounds, 0, 100);
  p.requireAllUsed("trajectory mode 'minimum_snap'");
  o.validate();
  // The curve must keep the vehicle's radius plus half the planner's margin clear: the other half
  // is the budget for tracking error.
  return MinimumSnapTrajectory(o).fit(plan.path, s.world, q.radius + 0.5 * s.planner_margin,
                                      plan.via_indices);
}

void progressLine(bool enabled, const std::string& text) {
  if (enabled) std::cerr << "cosim: " << text << std::endl;
}

// Step 1 for quadrotors that plan alone: each its own path.
void planEachQuadrotor(Scenario& scenario, const WorldModel& world,
                       const std::vector<std::size_t>& vehicles, const RunRequest& request,
                       QuadrotorPilots& q) {
  for (std::size_t v : vehicles) {
    progressLine(request.progress,
                 "planning " + scenario.vehicles[v].name + " with " +
                     (scenario.planner_name.empty() ? std::string("given waypoints")
                                                    : scenario.planner_name));
    const double radius = request.plan_as_point_mass ? 0.0 : world.vehicles()[v].params.radius;
    if (request.plan_as_point_mass) scenario.planner_margin = 0.0;
    q.plans.push_back(planVehicle(scenario, scenario.vehicles[v], radius, scenario.planner_params));
    for (const auto& name : q.plans.back().ignored_params)
      progressLine(request.progress, "note: planner." + name + " does not apply to " +
                                         scenario.planner_name + " (ignored)");
  }
  for (const auto& p : q.plans)
    if (!p.success) q.failure = "no path found: " + p.message;
}

// The reference of quadrotor k: seed 003's waypoint switching or a minimum-snap fit of its path
// (empty on failure, with q.failure set).
std::unique_ptr<ReferenceSource> singleReference(const Scenario& scenario, const VehicleSpec& spec,
                                                 const QuadrotorParams& airframe, std::size_t k,
                                                 QuadrotorPilots& q) {
  ParamSet traj = scenario.trajectory_params;
  if (scenario.trajectory_mode == "waypoints") {
    const double radius = traj.getDouble("switch_radius", 0.2, 0.01, 100.0);
    traj.requireAllUsed("trajectory mode 'waypoints'");
    return std::make_unique<WaypointReference>(q.plans[k].path.waypoints,
                                               spec.yaw_deg * M_PI / 180.0, radius);
  }
  MinimumSnapResult fit = fitMinimumSnap(scenario, spec, airframe, q.plans[k], traj);
  if (!fit.success) {
    q.failure = "no feasible trajectory: " + fit.message;
    return nullptr;
  }
  q.plans[k].trajectory_counters = fit.counters;
  return std::make_unique<TrajectoryReference>(std::move(fit.trajectory),
                                               spec.yaw_deg * M_PI / 180.0);
}

}  // namespace

QuadrotorPilots prepareQuadrotorPilots(Scenario& scenario, const WorldModel& world,
                                       const std::vector<std::size_t>& vehicles,
                                       const RunRequest& request) {
  QuadrotorPilots q;
  // 1. Plan a path for every quadrotor: jointly with a team planner, else each alone.
  std::vector<PiecewisePolynomialTrajectory> team_trajectories;
  const bool team = isMapfPlanner(scenario.planner_name);
  if (team) {
    progressLine(request.progress, "planning " + std::to_string(vehicles.size()) +
                                       " quadrotors as a team with " + scenario.planner_name);
    QuadrotorTeamFlight flight = planQuadrotorTeamFlight(scenario, world, vehicles, request);
    q.plans = std::move(flight.plans);
    q.failure = flight.failure;
    team_trajectories = std::move(flight.trajectories);
    scenario.trajectory_mode = "minimum_snap";  // what the team flies, whatever the file said
  } else {
    planEachQuadrotor(scenario, world, vehicles, request, q);
  }
  if (!q.failure.empty()) return q;

  // 2. Reference and controller per quadrotor.
  for (std::size_t k = 0; k < vehicles.size(); ++k) {
    const std::size_t v = vehicles[k];
    const VehicleSpec& spec = scenario.vehicles[v];
    const QuadrotorParams& airframe = q.airframes.emplace_back(
        believedAirframe(world.vehicles()[v].params, scenario.model_error));
    q.references.push_back(team ? std::make_unique<TrajectoryReference>(
                                      std::move(team_trajectories[k]), spec.yaw_deg * M_PI / 180.0)
                                : singleReference(scenario, spec, airframe, k, q));
    if (!q.references.back()) {
      q.pilots.clear();
      return q;
    }
    ParamSet gains = scenario.controller_gains;
    q.controllers.push_back(makeFlightController(scenario.controller_name, gains, airframe,
                                                 scenario.controller_drag_compensation));
    VehiclePilot pilot;
    pilot.believed_airframe = &airframe;
    pilot.controller = q.controllers.back().get();
    pilot.reference = q.references.back().get();
    pilot.goal = spec.goal();
    pilot.planned_path = q.plans[k].path.waypoints;
    q.pilots.push_back(pilot);
  }
  q.ready = true;
  return q;
}

}  // namespace cosim
