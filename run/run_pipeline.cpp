#include "run/run_pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <numeric>

#include "run/ground_run_pipeline.h"
#include "core/output_files.h"
#include "run/quadrotor_pilots.h"
#include "run/run_files.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "render/run_outputs.h"
#include "sim/flight_simulation.h"
#include "sim/run_log_io.h"
#include "sim/uav_separation_metrics.h"
#include "sim/world_model.h"

namespace cosim {

JsonObject flightMetricsJson(const FlightMetrics& m) {
  JsonObject j;
  j.add("reached_goal", m.reached_goal)
      .add("collisions", m.collisions)
      .add("planned_length_m", m.planned_length_m)
      .add("flown_length_m", m.flown_length_m)
      .add("flight_time_s", m.flight_time_s)
      .add("rmse_m", m.rmse_m)
      .add("max_error_m", m.max_error_m)
      .add("error_reference", m.error_reference)
      .add("min_clearance_m", m.min_clearance_m)
      .add("peak_thrust_fraction", m.peak_thrust_fraction)
      .add("saturated_fraction", m.saturated_fraction)
      .add("energy_proxy", m.energy_proxy)
      .add("max_speed_mps", m.max_speed_mps)
      .add("estimation_rmse_m", m.estimation_rmse_m);
  return j;
}

std::string flightFailureMessage(const std::string& end_reason) {
  if (end_reason == "diverged") return "the simulation diverged (NaN or runaway state)";
  if (end_reason == "unstable")
    return "the simulation became unstable (MuJoCo found bad numbers in the state or controls)";
  if (end_reason == "saturated")
    return "the rotors stayed saturated for over 2 s: the vehicle cannot follow its reference "
           "(check controller gains, trajectory limits, the model's mass and thrust)";
  if (end_reason != "goal") return "goal not reached within sim.max_time";
  return "collision";
}

double longestSaturation(const VehicleLog& v) {
  double longest = 0.0, since = -1.0;
  for (const auto& x : v.samples) {
    if (!x.saturated)
      since = -1.0;
    else if (since < 0.0)
      since = x.t;
    else
      longest = std::max(longest, x.t - since);
  }
  return longest;
}

bool stopRequestedFor(const RunRequest& request) {
  return request.interrupt && request.interrupt->load();
}

RunSummary interruptedRun() {
  RunSummary summary;
  summary.status = 1;
  summary.message = "interrupted";
  return summary;
}

RunSummary executeRun(Scenario& scenario, const RunRequest& request) {
  if (isGroundRun(scenario)) return executeGroundRun(scenario, request);
  // A quadrotor team flies in its members' downwash. Without a controller section it gets indi
  // rather than the single vehicle's cascade: measured on swarm32.yaml, cascade let a vehicle
  // sag about 0.2 m under another and break the planned separation (1 downwash violation),
  // while indi, geometric and dsl_pid kept it (closest 1.48, 1.17 and 1.30 ellipsoids).
  if (!scenario.controller_given && isMapfPlanner(scenario.planner_name))
    scenario.controller_name = "indi";
  RunSummary summary;
  const WorldModel world = WorldModel::build(scenario);

  // 1. Plan a path for every vehicle, and 2. its reference and controller.
  std::vector<std::size_t> all(scenario.vehicles.size());
  for (std::size_t v = 0; v < all.size(); ++v) all[v] = v;
  if (stopRequestedFor(request)) return interruptedRun();
  QuadrotorPilots quadrotors = prepareQuadrotorPilots(scenario, world, all, request);
  const std::vector<VehiclePlan>& plans = quadrotors.plans;
  const bool all_planned = quadrotors.ready;
  // A stop during planning ends the planners early: their "no path" is not a result.
  if (stopRequestedFor(request)) return interruptedRun();

  // 3. Fly.
  RunLog log;
  if (all_planned) {
    if (request.progress)
      std::cerr << "cosim: flying (physics step " << std::to_string(scenario.sim.timestep) << " s)"
                << std::endl;
    FlightOptions options;
    options.settings = scenario.sim;
    options.interrupt = request.interrupt;
    log = simulateFlight(world, scenario, quadrotors.pilots, options);
  } else {
    for (std::size_t v = 0; v < scenario.vehicles.size(); ++v) {
      VehicleLog& vl = log.vehicles.emplace_back();
      vl.name = scenario.vehicles[v].name;
      vl.goal = scenario.vehicles[v].goal();
    }
    log.end_reason = "no_path";
  }
  if (log.end_reason == "interrupted") {
    summary.status = 1;
    summary.message = "interrupted";
    return summary;  // nothing written that would look like a finished run
  }

  // 4. Evaluate, from the log.
  summary.sim_speed_x = log.wall_time > 0 ? log.sim_time / log.wall_time : 0.0;
  bool ok = all_planned && log.end_reason == "goal";
  for (std::size_t v = 0; v < log.vehicles.size(); ++v) {
    FlightMetrics m = computeFlightMetrics(log.vehicles[v], scenario.world,
                                           scenario.trajectory_mode != "waypoints");
    ok = ok && m.reached_goal && m.collisions == 0;
    summary.metrics.push_back(m);
  }
  if (!all_planned) summary.message = quadrotors.failure;
  if (all_planned && !ok) summary.message = flightFailureMessage(log.end_reason);
  if (log.mujoco_warnings > 0)
    std::cerr << "cosim: warning: MuJoCo reported " << log.mujoco_warnings
              << " warning(s); see mujoco_warnings in metrics.json\n";
  summary.status = ok ? 0 : 1;

  // 5. Write the run's files (each atomically).
  JsonObject metrics;
  const FlightMetrics& m0 = summary.metrics.front();
  int collisions = 0;
  bool reached = true;
  for (const auto& m : summary.metrics) {
    collisions += m.collisions;
    reached = reached && m.reached_goal;
  }
  double planning_ms = 0.0;
  for (const auto& p : plans) planning_ms += p.time_ms;
  metrics.add("reached_goal", reached)
      .add("collisions", collisions)
      .add("planner",
           scenario.planner_name.empty() ? std::string("waypoints") : scenario.planner_name)
      .add("planning_time_ms", planning_ms)
      .add("planned_length_m", m0.planned_length_m)
      .add("flown_length_m", m0.flown_length_m)
      .add("flight_time_s", m0.flight_time_s)
      .add("rmse_m", m0.rmse_m)
      .add("max_error_m", m0.max_error_m)
      .add("min_clearance_m", m0.min_clearance_m)
      .add("sim_speed_x", summary.sim_speed_x)
      .add("error_reference", m0.error_reference)
      .add("peak_thrust_fraction", m0.peak_thrust_fraction)
      .add("saturated_fraction", m0.saturated_fraction)
      .add("energy_proxy", m0.energy_proxy)
      .add("max_speed_mps", m0.max_speed_mps)
      .add("estimation_rmse_m", m0.estimation_rmse_m)
      .add("sensors", scenario.sensors.preset)
      .add("estimator", scenario.estimator.name)
      .add("controller", scenario.controller_name)
      .add("drag_compensation", scenario.controller_drag_compensation)
      .add("trajectory_mode", scenario.trajectory_mode)
      .add("vehicle_radius_m", world.vehicles().front().params.radius)
      .add("inflation_m", plans.front().inflation)
      .add("seed", static_cast<long>(scenario.sim.seed))
      .add("sim_time_s", log.sim_time)
      .add("wall_time_s", log.wall_time)
      .add("end_reason", log.end_reason)
      .add("mujoco_warnings", log.mujoco_warnings)
      .add("fault", log.end_reason == "diverged" || log.end_reason == "unstable" ||
                            log.end_reason == "saturated"
                        ? log.end_reason
                        : std::string("none"))
      .add("longest_saturation_s", std::accumulate(log.vehicles.begin(), log.vehicles.end(), 0.0,
                                                   [](double longest, const VehicleLog& v) {
                                                     return std::max(longest, longestSaturation(v));
                                                   }))
      .add("status", summary.status)
      .add("message", summary.message)
      .add("planner_counters", plans.front().counters)
      .add("planner_params", plans.front().params)
      .add("trajectory_counters", plans.front().trajectory_counters);
  std::vector<JsonObject> per_vehicle;
  for (std::size_t v = 0; v < summary.metrics.size(); ++v) {
    JsonObject j = flightMetricsJson(summary.metrics[v]);
    j.add("name", log.vehicles[v].name).add("model", scenario.vehicles[v].model);
    per_vehicle.push_back(j);
  }
  if (log.vehicles.size() > 1) {
    // A team of quadrotors: how close they came to each other (sim/uav_separation_metrics.h).
    std::vector<std::size_t> all(log.vehicles.size());
    std::vector<SeparationEllipsoid> ellipsoids;
    for (std::size_t v = 0; v < all.size(); ++v) {
      all[v] = v;
      const QuadrotorParams& q = world.vehicles()[v].params;
      ellipsoids.push_back({q.separation_radius, q.separation_height});
    }
    const UavSeparationMetrics u = uavSeparationMetrics(log, all, ellipsoids);
    metrics.add("uav_contacts", u.uav_contacts)
        .add("min_uav_separation_m", u.min_uav_separation)
        .add("downwash_violations", u.downwash_violations);
  }
  metrics.addArray("vehicles", per_vehicle);

  // Interrupted while rendering: no index.html, no metrics.json, nothing that looks finished.
  if (!writeRunFiles(world, scenario, log, request, all_planned, metrics, summary))
    return interruptedRun();
  summary.metrics_json = std::move(metrics);
  summary.log = std::move(log);
  return summary;
}

}  // namespace cosim
