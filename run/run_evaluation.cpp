#include "run/run_evaluation.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "control/piecewise_polynomial_reference.h"
#include "run/navigation_driver.h"
#include "run/pooled_metrics.h"

namespace cosim {

namespace {

// A robot's tracking error is against its timed plan (a time-parametrised reference); a
// quadrotor's against its trajectory or given reference, or its path when it switches between
// waypoints.
std::vector<FlightMetrics> eachVehicle(const Scenario& s, const RunSetup& setup,
                                       const RunLog& log) {
  const bool quadrotor_trajectory =
      setup.quadrotor_sections.trajectory.mode != TrajectoryMode::Waypoints;
  std::vector<FlightMetrics> each;
  for (std::size_t v = 0; v < log.vehicles.size(); ++v)
    each.push_back(computeFlightMetrics(log.vehicles[v], s.world,
                                        s.vehicles[v].kind == VehicleKind::GroundRobot ||
                                            quadrotor_trajectory || s.vehicles[v].reference));
  return each;
}

RobotSchedule robotSchedule(const RunSetup& setup, const RunPlan& plan, const RunLog& log) {
  RobotSchedule s;
  for (std::size_t k = 0; k < setup.robots.size(); ++k) {
    const double arrival = log.vehicles[setup.robots[k]].arrival_time;
    const double planned =
        plan.drivable() && k < plan.robots.paths.size() ? plan.robots.paths[k].endTime() : -1.0;
    s.planned_arrival_s.push_back(planned);
    s.planned_makespan_s = std::max(s.planned_makespan_s, planned);
    s.executed_makespan_s = std::max(s.executed_makespan_s, arrival);
    s.sum_of_arrival_times_s += std::max(arrival, 0.0);
  }
  return s;
}

std::optional<UavSeparationMetrics> separation(const RunSetup& setup, const WorldModel& world,
                                               const RunLog& log) {
  if (setup.quadrotors.size() < 2) return std::nullopt;
  std::vector<SeparationEllipsoid> ellipsoids;
  for (std::size_t v : setup.quadrotors)
    ellipsoids.push_back({world.vehicles()[v].params.separation_radius,
                          world.vehicles()[v].params.separation_height});
  return uavSeparationMetrics(log, setup.quadrotors, ellipsoids);
}

std::string formatSeconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g s", s);
  return buf;
}

// Why a vehicle flying a given reference did not reach its last point, or "" for none: the
// reference outlasts sim.max_time, or the vehicle had not settled there by the end of the run.
std::string givenReferenceShortfall(const Scenario& s, const RunLog& log) {
  std::string why;
  for (std::size_t v = 0; v < s.vehicles.size() && v < log.vehicles.size() && why.empty(); ++v) {
    const auto& given = s.vehicles[v].reference;
    if (!given || log.vehicles[v].reached_goal) continue;
    const std::string who = s.vehicles.size() > 1 ? s.vehicles[v].name + ": " : std::string();
    if (given->duration() > s.sim.max_time)
      why = who + "the reference lasts " + formatSeconds(given->duration()) +
            ", longer than sim.max_time " + formatSeconds(s.sim.max_time);
    else
      why = who + "the reference ended at " + formatSeconds(given->duration()) +
            " but the vehicle had not settled within sim.goal_tolerance of its last point by " +
            "the end of the run at " + formatSeconds(log.sim_time);
  }
  return why;
}

// Why the run failed its task, or "" if it did not: the plan's failure, else the simulation's
// end, else a vehicle that missed its goal (for a given reference: why) or touched something. A
// team plan with conflicts fails the run whatever the physics made of it.
std::string failureMessage(const Scenario& s, const RunPlan& plan, const RunLog& log,
                           const RunMetrics& m) {
  std::string why;
  if (!plan.drivable())
    why = plan.message;
  else if (m.end == RunEnd::GaveUp)
    why = "the navigator gave up" +
          (plan.robots.navigator && !plan.robots.navigator->message().empty()
               ? ": " + plan.robots.navigator->message()
               : std::string());
  else if (isFault(m.end))
    why = faultMessage(m.end);
  else if (m.end != RunEnd::Goal || !m.reached_goal)
    why = givenReferenceShortfall(s, log);
  else if (m.collisions > 0)
    why = "collision";
  if (why.empty() && plan.drivable() && (m.end != RunEnd::Goal || !m.reached_goal))
    why = "goal not reached within sim.max_time";
  if (plan.status == PlanStatus::Conflicting) why = plan.message + (why.empty() ? "" : "; " + why);
  return why;
}

void evaluateOutcome(const Scenario& s, const RunPlan& plan, const RunLog& log, RunMetrics& m) {
  m.end = log.end_reason;
  m.reached_goal = plan.drivable();
  m.min_clearance_m = m.vehicles.empty() ? 0.0 : std::numeric_limits<double>::infinity();
  for (const FlightMetrics& v : m.vehicles) {
    m.reached_goal = m.reached_goal && v.reached_goal;
    m.min_clearance_m = std::min(m.min_clearance_m, v.min_clearance_m);
  }
  m.collisions = m.contacts.total();
  m.message = failureMessage(s, plan, log, m);
  m.status = m.message.empty() ? 0 : 1;
}

}  // namespace

RunMetrics evaluateRun(const Scenario& scenario, const RunSetup& setup, const WorldModel& world,
                       const RunPlan& plan, const RunLog& log) {
  RunMetrics m;
  m.sim_speed_x = log.wall_time > 0 ? log.sim_time / log.wall_time : 0.0;
  m.vehicles = eachVehicle(scenario, setup, log);
  std::vector<VehicleKind> kinds(log.vehicles.size());
  for (std::size_t v = 0; v < kinds.size(); ++v) kinds[v] = scenario.vehicles[v].kind;
  m.contacts = teamContacts(log, kinds);
  m.team = poolFlightMetrics(m.vehicles, log, setup.primary());
  if (setup.primaryKind() == VehicleKind::GroundRobot) {
    m.uavs = poolFlightMetrics(m.vehicles, log, setup.quadrotors);
    m.schedule = robotSchedule(setup, plan, log);
  }
  m.separation = separation(setup, world, log);
  for (std::size_t v : setup.quadrotors)
    m.longest_saturation_s = std::max(m.longest_saturation_s, longestSaturation(log.vehicles[v]));
  evaluateOutcome(scenario, plan, log, m);
  return m;
}

}  // namespace cosim
