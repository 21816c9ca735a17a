#include "run/run_evaluation.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "control/piecewise_polynomial_reference.h"
#include "run/navigation_driver.h"
#include "run/pooled_metrics.h"
#include "run/run_end.h"
#include "run/team_contacts.h"

namespace cosim {

namespace {

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

void evaluateOutcome(const Scenario& s, const RunPlan& plan, RunRecord& r) {
  RunMetrics& m = r.metrics;
  m.end = r.log.end_reason;
  m.reached_goal = plan.drivable();
  m.min_clearance_m = m.vehicles.empty() ? 0.0 : std::numeric_limits<double>::infinity();
  for (const FlightMetrics& v : m.vehicles) {
    m.reached_goal = m.reached_goal && v.reached_goal;
    m.min_clearance_m = std::min(m.min_clearance_m, v.min_clearance_m);
  }
  m.collisions = m.contacts.total();
  r.message = failureMessage(s, plan, r.log, m);
  r.outcome = r.message.empty() ? RunOutcome::Succeeded : RunOutcome::TaskFailed;
}

PlanFigures planFigures(const RunSetup& setup, const RunPlan& plan) {
  PlanFigures f;
  f.primary = plan.primarySummary(setup);
  f.robot_inflation = plan.robots.summary.inflation;
  f.quadrotor_inflation = plan.quadrotors.summary.inflation;
  f.cruise_speed_mps = plan.robots.cruise_speed;
  f.trajectory_counters = plan.quadrotors.trajectory_counters;
  f.verification = plan.verification;
  return f;
}

}  // namespace

FlightMetrics evaluateReferenceFlight(const Scenario& s, const RunLog& log) {
  return computeFlightMetrics(log.vehicles.at(0), s.world, ErrorReference::Trajectory);
}

void trackVehicles(const RunSetup& setup, const RunLog& log, RunMetrics& m) {
  m.tracking_errors.clear();
  for (std::size_t v = 0; v < log.vehicles.size(); ++v)
    m.tracking_errors.push_back(trackingErrors(log.vehicles[v], setup.vehicles[v].error_reference));
}

void evaluateVehicles(const Scenario& s, const RunSetup& setup, const RunLog& log, RunMetrics& m) {
  m.vehicles.clear();
  for (std::size_t v = 0; v < log.vehicles.size(); ++v)
    m.vehicles.push_back(
        computeFlightMetrics(log.vehicles[v], s.world, setup.vehicles[v].error_reference));
  trackVehicles(setup, log, m);
}

RunRecord recordOfLog(const Scenario& scenario, RunLog log,
                      std::shared_ptr<const WorldModel> world) {
  RunRecord r;
  r.setup = resolveRun(scenario, false);
  r.log = std::move(log);
  r.world = std::move(world);
  evaluateVehicles(scenario, r.setup, r.log, r.metrics);
  return r;
}

RunRecord recordOfLog(const Scenario& scenario, RunLog log, const WorldModel& world) {
  // Not owned: the aliasing constructor with an empty owner.
  return recordOfLog(
      scenario, std::move(log),
      std::shared_ptr<const WorldModel>(std::shared_ptr<const WorldModel>(), &world));
}

RunRecord evaluateRun(const Scenario& scenario, const RunSetup& setup,
                      const std::shared_ptr<const WorldModel>& world, const RunPlan& plan,
                      RunLog log) {
  RunRecord r;
  r.setup = setup;
  r.plans = vehiclePlans(scenario, setup, plan);
  r.planning = planFigures(setup, plan);
  r.world = world;
  r.log = std::move(log);
  RunMetrics& m = r.metrics;
  m.sim_speed_x = r.log.wall_time > 0 ? r.log.sim_time / r.log.wall_time : 0.0;
  evaluateVehicles(scenario, setup, r.log, m);
  std::vector<VehicleKind> kinds(r.log.vehicles.size());
  for (std::size_t v = 0; v < kinds.size(); ++v) kinds[v] = setup.vehicles[v].kind;
  m.contacts = teamContacts(r.log, kinds);
  m.team = poolFlightMetrics(m.vehicles, r.log, setup.primary());
  if (setup.primaryKind() == VehicleKind::GroundRobot) {
    m.uavs = poolFlightMetrics(m.vehicles, r.log, setup.quadrotors);
    m.schedule = robotSchedule(setup, plan, r.log);
  }
  m.separation = separation(setup, *world, r.log);
  for (std::size_t v : setup.quadrotors)
    m.longest_saturation_s = std::max(m.longest_saturation_s, longestSaturation(r.log.vehicles[v]));
  evaluateOutcome(scenario, plan, r);
  return r;
}

}  // namespace cosim
