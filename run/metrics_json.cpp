#include "run/metrics_json.h"

#include <algorithm>

#include "control/piecewise_polynomial_reference.h"
#include "run/run_end.h"

namespace cosim {

namespace {

// What metrics.json is made of: the record of a run of the scenario.
struct RecordOf {
  const Scenario& scenario;
  const RunRecord& record;
  const RunSetup& setup = record.setup;
  const RunMetrics& metrics = record.metrics;
  const RunLog& log = record.log;
  const PlanFigures& plan = record.planning;
};

std::string plannerName(const std::string& name) {
  return name.empty() ? std::string("waypoints") : name;
}

// metrics.json's "fault": the simulation's end when it was a fault of the vehicles.
std::string faultName(const RecordOf& r) {
  return isFault(r.metrics.end) ? runEndName(r.log.end_reason) : "none";
}

// A quadrotor team's verification flights: each round's conflicts and the repair it led to.
JsonObject planVerificationJson(const PlanVerificationReport& v) {
  std::vector<JsonObject> rounds;
  for (const VerificationRound& r : v.rounds) {
    std::vector<JsonObject> conflicts;
    for (const FlownConflict& c : r.conflicts) {
      JsonObject o;
      o.add("a", c.a).add("b", c.b).add("t_s", c.t).add("separation", c.separation);
      conflicts.push_back(o);
    }
    JsonObject o;
    o.add("round", r.round)
        .add("flight_wall_s", r.flight_wall_s)
        .add("min_separation", r.min_separation)
        .add("uav_contacts", r.uav_contacts)
        .add("arrived", r.arrived)
        .add("peak_thrust_fraction", r.peak_thrust_fraction)
        .addArray("conflicts", conflicts)
        .add("repair", r.repair);
    rounds.push_back(o);
  }
  JsonObject j;
  j.add("rounds_flown", static_cast<int>(v.rounds.size()))
      .add("clean", v.clean)
      .add("seconds", v.seconds)
      .addArray("rounds", rounds);
  return j;
}

// What every run reports first: the outcome and the top-level vehicles' tracking.
void addHeadline(JsonObject& j, const RecordOf& r) {
  const RunMetrics& m = r.metrics;
  j.add("reached_goal", m.reached_goal)
      .add("collisions", m.collisions)
      .add("planner", plannerName(r.scenario.motion.planner.name))
      .add("planning_time_ms", r.plan.primary.time_ms)
      .add("planned_length_m", m.team.planned_length_m)
      .add("flown_length_m", m.team.flown_length_m)
      .add("flight_time_s", m.team.flight_time_s)
      .add("rmse_m", m.team.rmse_m)
      .add("max_error_m", m.team.max_error_m)
      .add("min_clearance_m", m.min_clearance_m)
      .add("sim_speed_x", m.sim_speed_x)
      // A robot's reference is its timed plan.
      .add("error_reference", errorReferenceKey(m.team.error_reference));
}

// A flight: its quadrotors' airframe figures and how they were flown.
void addFlight(JsonObject& j, const RecordOf& r) {
  const FlightMetrics& t = r.metrics.team;
  const Scenario& s = r.scenario;
  double radius = 0.0;
  for (std::size_t v : r.setup.quadrotors)
    radius = std::max(radius, r.record.world->vehicles()[v].params.radius);
  j.add("peak_thrust_fraction", t.peak_thrust_fraction)
      .add("saturated_fraction", t.saturated_fraction)
      .add("energy_proxy", t.energy_proxy)
      .add("max_speed_mps", t.max_speed_mps)
      .add("estimation_rmse_m", t.estimation_rmse_m)
      .add("sensors", s.sensors.preset)
      .add("estimator", estimatorName(s.estimator.kind))
      .add("controller", r.setup.primarySections().controller.name)
      .add("drag_compensation", r.setup.primarySections().controller.drag_compensation)
      .add("trajectory_mode", trajectoryModeName(r.setup.primarySections().trajectory.mode))
      .add("vehicle_radius_m", radius)
      .add("inflation_m", r.plan.quadrotor_inflation);
}

// A run with ground robots: their contacts, closest approaches and schedule.
void addRobots(JsonObject& j, const RecordOf& r) {
  const TeamContacts& c = r.metrics.contacts;
  const RobotSchedule& s = r.metrics.schedule;
  j.add("robots", static_cast<int>(r.setup.robots.size()))
      .add("robot_contacts", c.robot_contacts)
      .add("obstacle_contacts", c.obstacle_contacts)
      .add("moving_obstacle_contacts", c.moving_obstacle_contacts)
      .add("moving_obstacles", static_cast<int>(r.scenario.moving_obstacles.size()))
      .add("min_robot_distance_m", c.min_robot_distance_m)
      .add("min_moving_obstacle_distance_m", c.min_moving_obstacle_distance_m)
      .add("planned_makespan_s", s.planned_makespan_s)
      .add("executed_makespan_s", s.executed_makespan_s)
      .add("sum_of_arrival_times_s", s.sum_of_arrival_times_s)
      .add("cruise_speed_mps", r.plan.cruise_speed_mps)
      .add("inflation_m", r.plan.robot_inflation);
}

// The quadrotors over ground robots, driven by the `aerial` sections.
void addQuadrotorsOverRobots(JsonObject& j, const RecordOf& r) {
  if (r.setup.quadrotors.empty()) return;
  const MotionSections& air = r.setup.quadrotor_sections;
  const RunMetrics& m = r.metrics;
  j.add("uavs", static_cast<int>(r.setup.quadrotors.size()))
      .add("robot_uav_contacts", m.contacts.robot_uav_contacts)
      .add("uav_contacts", m.contacts.uav_contacts)
      .add("uav_planner", plannerName(air.planner.name))
      .add("uav_trajectory_mode", trajectoryModeName(air.trajectory.mode))
      .add("uav_controller", air.controller.name)
      .add("uav_rmse_m", m.uavs.rmse_m)
      .add("uav_max_error_m", m.uavs.max_error_m)
      .add("longest_saturation_s", m.longest_saturation_s)
      .add("fault", faultName(r));
  if (m.separation)
    j.add("min_uav_separation_m", m.separation->min_uav_separation)
        .add("downwash_violations", m.separation->downwash_violations);
}

// The run itself: its seed, its time, how it ended, and the planner's figures.
void addRunFacts(JsonObject& j, const RecordOf& r) {
  const RunMetrics& m = r.metrics;
  const PlanSummary& plan = r.plan.primary;
  j.add("seed", static_cast<long>(r.scenario.sim.seed))
      .add("sim_time_s", r.log.sim_time)
      .add("wall_time_s", r.log.wall_time)
      .add("end_reason", runEndName(r.log.end_reason))
      .add("mujoco_warnings", r.log.mujoco_warnings);
  if (r.setup.primaryKind() != VehicleKind::GroundRobot)
    j.add("fault", faultName(r)).add("longest_saturation_s", m.longest_saturation_s);
  j.add("status", r.record.exitStatus())
      .add("message", r.record.message)
      .add("planner_counters", plan.counters)
      .add("planner_params", plan.params);
  if (r.setup.primaryKind() == VehicleKind::GroundRobot) return;
  j.add("trajectory_counters", r.plan.trajectory_counters);
  if (m.separation)  // a team of quadrotors: how close they came to each other
    j.add("uav_contacts", m.contacts.uav_contacts)
        .add("min_uav_separation_m", m.separation->min_uav_separation)
        .add("downwash_violations", m.separation->downwash_violations);
  if (r.plan.verification.ran)
    j.add("plan_verification", planVerificationJson(r.plan.verification));
}

JsonObject quadrotorEntry(const RecordOf& r, std::size_t v) {
  const VehicleLog& vl = r.log.vehicles[v];
  JsonObject j = flightMetricsJson(r.metrics.vehicles[v]);
  j.add("name", vl.name).add("model", r.scenario.vehicles[v].model);
  if (const auto& given = r.scenario.vehicles[v].reference)  // rmse_m covers its duration
    j.add("reference_file", r.scenario.vehicles[v].reference_file.string())
        .add("reference_duration_s", given->duration())
        .add("reference_timescale", given->placement().timescale);
  if (r.setup.primaryKind() == VehicleKind::GroundRobot)
    j.add("kind", "quadrotor").add("arrival_time_s", vl.arrival_time).add("radius_m", vl.radius);
  return j;
}

// Robot k of the run, scenario.vehicles[v].
JsonObject robotEntry(const RecordOf& r, std::size_t v, std::size_t k) {
  const VehicleLog& vl = r.log.vehicles[v];
  const FlightMetrics& m = r.metrics.vehicles[v];
  JsonObject j;
  j.add("name", vl.name)
      .add("model", r.scenario.vehicles[v].model)
      .add("kind", "ground_robot")
      .add("reached_goal", m.reached_goal)
      .add("arrival_time_s", vl.arrival_time)
      .add("planned_arrival_s", r.metrics.schedule.planned_arrival_s[k])
      .add("contacts", m.collisions)
      .add("planned_length_m", m.planned_length_m)
      .add("flown_length_m", m.flown_length_m)
      .add("rmse_m", m.rmse_m)
      .add("max_error_m", m.max_error_m)
      .add("min_clearance_m", m.min_clearance_m)
      .add("max_speed_mps", m.max_speed_mps)
      .add("radius_m", vl.radius);
  return j;
}

std::vector<JsonObject> vehicleEntries(const RecordOf& r) {
  std::vector<JsonObject> entries;
  for (std::size_t v = 0, k = 0; v < r.log.vehicles.size(); ++v)
    entries.push_back(r.setup.vehicles[v].kind == VehicleKind::GroundRobot ? robotEntry(r, v, k++)
                                                                           : quadrotorEntry(r, v));
  return entries;
}

}  // namespace

JsonObject flightMetricsJson(const FlightMetrics& m) {
  JsonObject j;
  j.add("reached_goal", m.reached_goal)
      .add("collisions", m.collisions)
      .add("planned_length_m", m.planned_length_m)
      .add("flown_length_m", m.flown_length_m)
      .add("flight_time_s", m.flight_time_s)
      .add("rmse_m", m.rmse_m)
      .add("max_error_m", m.max_error_m)
      .add("error_reference", errorReferenceKey(m.error_reference))
      .add("min_clearance_m", m.min_clearance_m)
      .add("peak_thrust_fraction", m.peak_thrust_fraction)
      .add("saturated_fraction", m.saturated_fraction)
      .add("energy_proxy", m.energy_proxy)
      .add("max_speed_mps", m.max_speed_mps)
      .add("estimation_rmse_m", m.estimation_rmse_m);
  return j;
}

JsonObject runMetricsJson(const Scenario& scenario, const RunRecord& record) {
  const RecordOf r{scenario, record};
  JsonObject j;
  addHeadline(j, r);
  if (r.setup.primaryKind() == VehicleKind::GroundRobot) {
    addRobots(j, r);
    addQuadrotorsOverRobots(j, r);
  } else {
    addFlight(j, r);
  }
  addRunFacts(j, r);
  j.addArray("vehicles", vehicleEntries(r));
  return j;
}

}  // namespace cosim
