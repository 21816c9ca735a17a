#include "experiments/cli/run_pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "control/waypoint_reference.h"
#include "experiments/cli/ground_run_pipeline.h"
#include "experiments/cli/output_files.h"
#include "experiments/cli/scenario_planning.h"
#include "planning/input_error.h"
#include "planning/trajectory/minimum_snap_trajectory.h"
#include "render/run_outputs.h"
#include "sim/controller_factory.h"
#include "sim/flight_simulation.h"
#include "sim/json_writer.h"
#include "sim/run_log_io.h"
#include "sim/trajectory_reference.h"
#include "sim/world_model.h"

namespace cosim {

namespace {

// A minimum-snap trajectory through the planned path, within the airframe's limits: speed and
// acceleration from the scenario's trajectory section, thrust from the model (keeping 20 % of
// the rotors' thrust for control).
MinimumSnapResult fitMinimumSnap(const Scenario& s, const VehicleSpec& spec,
                                 const QuadrotorParams& q, const Path& path, ParamSet& p) {
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
  return MinimumSnapTrajectory(o).fit(path, s.world, q.radius + 0.5 * s.planner_margin);
}

JsonObject metricsJson(const FlightMetrics& m) {
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
      .add("max_speed_mps", m.max_speed_mps);
  return j;
}

// Why a flight that planned fine did not succeed, from the simulation's end_reason.
std::string runFailureMessage(const std::string& end_reason) {
  if (end_reason == "diverged") return "the simulation diverged (NaN or runaway state)";
  if (end_reason == "unstable")
    return "the simulation became unstable (MuJoCo found bad numbers in the state or controls)";
  if (end_reason == "saturated")
    return "the rotors stayed saturated for over 2 s: the vehicle cannot follow its reference "
           "(check controller gains, trajectory limits, the model's mass and thrust)";
  if (end_reason != "goal") return "goal not reached within sim.max_time";
  return "collision";
}

// The longest stretch of continuous mixer saturation of any vehicle, in seconds.
double longestSaturation(const RunLog& log) {
  double longest = 0.0;
  for (const auto& v : log.vehicles) {
    double since = -1.0;
    for (const auto& x : v.samples) {
      if (!x.saturated) since = -1.0;
      else if (since < 0.0) since = x.t;
      else longest = std::max(longest, x.t - since);
    }
  }
  return longest;
}

void progressLine(bool enabled, const std::string& text) {
  if (enabled) std::cerr << "cosim: " << text << std::endl;
}

}  // namespace

RunSummary executeRun(Scenario& scenario, const RunRequest& request) {
  if (isGroundRun(scenario)) return executeGroundRun(scenario, request);
  RunSummary summary;
  const WorldModel world = WorldModel::build(scenario);
  const auto& dir = request.out_dir;

  // 1. Plan a path for every vehicle.
  std::vector<VehiclePlan> plans;
  for (std::size_t v = 0; v < scenario.vehicles.size(); ++v) {
    progressLine(request.progress, "planning " + scenario.vehicles[v].name + " with " +
                                       (scenario.planner_name.empty() ? std::string("given waypoints") : scenario.planner_name));
    const double radius = request.plan_as_point_mass ? 0.0 : world.vehicles()[v].params.radius;
    if (request.plan_as_point_mass) scenario.planner_margin = 0.0;
    plans.push_back(planVehicle(scenario, scenario.vehicles[v], radius, scenario.planner_params));
    for (const auto& name : plans.back().ignored_params)
      progressLine(request.progress, "note: planner." + name + " does not apply to " +
                                         scenario.planner_name + " (ignored)");
  }

  // 2. Reference and controller per vehicle.
  std::vector<std::unique_ptr<ReferenceSource>> references;
  std::vector<std::unique_ptr<FlightController>> controllers;
  std::vector<VehiclePilot> pilots;
  std::string trajectory_failure;
  bool all_planned = std::all_of(plans.begin(), plans.end(), [](const VehiclePlan& p) { return p.success; });
  if (all_planned) {
    for (std::size_t v = 0; v < scenario.vehicles.size(); ++v) {
      const VehicleSpec& spec = scenario.vehicles[v];
      ParamSet traj = scenario.trajectory_params;
      if (scenario.trajectory_mode == "waypoints") {
        const double radius = traj.getDouble("switch_radius", 0.2, 0.01, 100.0);
        traj.requireAllUsed("trajectory mode 'waypoints'");
        references.push_back(std::make_unique<WaypointReference>(
            plans[v].path.waypoints, spec.yaw_deg * M_PI / 180.0, radius));
      } else {
        MinimumSnapResult fit = fitMinimumSnap(scenario, spec, world.vehicles()[v].params, plans[v].path, traj);
        if (!fit.success) {
          trajectory_failure = "no feasible trajectory: " + fit.message;
          break;
        }
        plans[v].trajectory_counters = fit.counters;
        references.push_back(std::make_unique<TrajectoryReference>(std::move(fit.trajectory),
                                                                   spec.yaw_deg * M_PI / 180.0));
      }
      ParamSet gains = scenario.controller_gains;
      controllers.push_back(makeFlightController(scenario.controller_name, gains, world.vehicles()[v].params));
      VehiclePilot pilot;
      pilot.controller = controllers.back().get();
      pilot.reference = references.back().get();
      pilot.goal = spec.goal();
      pilot.planned_path = plans[v].path.waypoints;
      pilots.push_back(pilot);
    }
  }

  if (!trajectory_failure.empty()) all_planned = false;

  // 3. Fly.
  RunLog log;
  if (all_planned) {
    progressLine(request.progress, "flying (physics step " + std::to_string(scenario.sim.timestep) + " s)");
    FlightOptions options;
    options.settings = scenario.sim;
    options.interrupt = request.interrupt;
    log = simulateFlight(world, scenario, pilots, options);
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
    FlightMetrics m = computeFlightMetrics(log.vehicles[v], scenario.world, scenario.trajectory_mode != "waypoints");
    ok = ok && m.reached_goal && m.collisions == 0;
    summary.metrics.push_back(m);
  }
  if (!all_planned) {
    for (const auto& p : plans)
      if (!p.success) summary.message = "no path found: " + p.message;
    if (!trajectory_failure.empty()) summary.message = trajectory_failure;
  }
  if (all_planned && !ok)
    summary.message = runFailureMessage(log.end_reason);
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
      .add("planner", scenario.planner_name.empty() ? std::string("waypoints") : scenario.planner_name)
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
      .add("controller", scenario.controller_name)
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
      .add("longest_saturation_s", longestSaturation(log))
      .add("status", summary.status)
      .add("message", summary.message)
      .add("planner_counters", plans.front().counters)
      .add("planner_params", plans.front().params)
      .add("trajectory_counters", plans.front().trajectory_counters);
  std::vector<JsonObject> per_vehicle;
  for (std::size_t v = 0; v < summary.metrics.size(); ++v) {
    JsonObject j = metricsJson(summary.metrics[v]);
    j.add("name", log.vehicles[v].name).add("model", scenario.vehicles[v].model);
    per_vehicle.push_back(j);
  }
  metrics.addArray("vehicles", per_vehicle);

  writeFileAtomically(dir / "scenario.yaml", scenario.effective_yaml);
  writeFileAtomically(dir / "run.json", JsonObject()
                                            .add("scenario_file", std::filesystem::absolute(scenario.file).string())
                                            .str() + "\n");
  writeFileAtomically(dir / "path.csv", pathCsv(log));
  writeFileAtomically(dir / "timeseries.csv", timeseriesCsv(log));

  // 6. Render from the log: final.png, figures/, the videos, and index.html showing them.
  RenderedRun rendered;
  if (all_planned && (request.images || request.video)) {
    RunRenderRequest render_request;
    render_request.images = request.images;
    render_request.video = request.video;
    render_request.progress = request.progress;
    rendered = renderRunOutputs(world, scenario, log, dir, render_request);
  }
  writeRunReport(dir, scenario, metrics.str(), summary.status == 0 ? "" : summary.message, rendered);
  // metrics.json last: its presence means the run's files are complete.
  writeFileAtomically(dir / "metrics.json", metrics.str() + "\n");
  return summary;
}

}  // namespace cosim
