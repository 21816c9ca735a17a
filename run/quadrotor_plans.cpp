#include "run/quadrotor_plans.h"

#include <cmath>

#include "control/piecewise_polynomial_reference.h"
#include "control/waypoint_reference.h"
#include "planning/trajectory/minimum_snap_trajectory.h"
#include "run/quadrotor_team_planning.h"
#include "run/run_pipeline.h"
#include "sim/model_error.h"
#include "sim/trajectory_reference.h"

namespace cosim {

namespace {

// A minimum-snap trajectory through the planned path, within the airframe's limits: speed and
// acceleration from the scenario's trajectory section, thrust from the model (keeping 20 % of
// the rotors' thrust for control).
MinimumSnapResult fitMinimumSnap(const Scenario& s, const PlannerSection& planner,
                                 const QuadrotorParams& q, const VehiclePlan& plan, ParamSet& p) {
  MinimumSnapOptions o;
  o.limits.max_speed = p.getDouble("max_speed", 3.0, 0.01, 100.0);
  o.limits.max_acceleration = p.getDouble("max_acceleration", 3.0, 0.01, 100.0);
  o.limits.gravity = q.gravity;
  o.limits.max_thrust_accel = 0.8 * 4.0 * q.max_thrust / q.mass;
  o.time_penalty = p.getDouble("k_t", o.time_penalty, 0.0, 1e9);
  o.optimize_times = p.getBool("optimize_times", o.optimize_times);
  o.shortcut = p.getBool("shortcut", o.shortcut);
  o.max_repair_rounds = p.getInt("max_repair_rounds", o.max_repair_rounds, 0, 100);
  p.requireAllUsed("trajectory mode 'minimum_snap'");
  o.validate();
  // The curve must keep the vehicle's radius plus half the planner's margin clear: the other half
  // is the budget for tracking error.
  return MinimumSnapTrajectory(o).fit(plan.path, s.world, q.radius + 0.5 * planner.margin,
                                      plan.via_indices);
}

// A vehicle flying a given reference is not planned: its path is the reference, sampled (every
// 20 ms, at most 2000 points) for path.csv and the figures.
VehiclePlan givenReferencePlan(const VehicleSpec& spec, double inflation) {
  VehiclePlan plan;
  plan.success = true;
  plan.status = PlannerStatus::ExactSolution;
  plan.inflation = inflation;
  plan.path.waypoints = spec.reference->sampledPath(2000, 0.02);
  plan.via_indices = {plan.path.waypoints.size() - 1};
  return plan;
}

// Each quadrotor its own path; the last failure, if any, is the group's.
void planEachQuadrotor(const Scenario& s, const PlannerSection& planner, const WorldModel& world,
                       const std::vector<std::size_t>& vehicles, const RunRequest& request,
                       const RunReporter& report, QuadrotorPlans& q) {
  for (std::size_t v : vehicles) {
    if (s.vehicles[v].reference) {
      report.message(s.vehicles[v].name + " flies its reference " +
                     s.vehicles[v].reference_file.filename().string() + " (not planned)");
      q.plans.push_back(givenReferencePlan(s.vehicles[v], world.vehicles()[v].params.radius));
      continue;
    }
    report.message("planning " + s.vehicles[v].name + " with " +
                   (planner.name.empty() ? std::string("given waypoints") : planner.name));
    const double radius = request.plan_as_point_mass ? 0.0 : world.vehicles()[v].params.radius;
    q.plans.push_back(planVehicle(s, planner, s.vehicles[v], radius));
    for (const auto& name : q.plans.back().set_aside_params)
      report.message("note: the scenario's planner." + name + " does not apply to " + planner.name +
                     " (chosen by an override): set aside");
  }
  for (const auto& p : q.plans) {
    if (p.success) continue;
    q.status = PlanStatus::NoPath;
    q.failure = "no path found: " + p.message;
  }
  q.summary = summarizeSeparatePlans(q.plans);
}

// The team's paths and timed trajectories, planned jointly.
void planQuadrotorTeam(const Scenario& s, const MotionSections& m, const WorldModel& world,
                       const std::vector<std::size_t>& vehicles, const RunRequest& request,
                       const RunReporter& report, const TeamRepairs& repairs, QuadrotorPlans& q) {
  report.message("planning " + std::to_string(vehicles.size()) + " quadrotors as a team with " +
                 m.planner.name);
  QuadrotorTeamFlight flight =
      planQuadrotorTeamFlight(s, m, world, vehicles, q.airframes, request, repairs);
  q.plans = std::move(flight.plans);
  q.summary = summarizeSeparatePlans(q.plans);
  if (!q.plans.empty()) q.summary.counters = q.plans.front().counters;  // the team's, once
  if (!flight.success) {
    q.status = PlanStatus::NoPath;
    q.failure = flight.failure;
    return;
  }
  for (std::size_t k = 0; k < vehicles.size(); ++k)
    q.references.push_back(std::make_unique<TrajectoryReference>(
        std::move(flight.trajectories[k]), s.vehicles[vehicles[k]].yaw_deg * M_PI / 180.0));
}

// The reference of quadrotor k planned alone: seed 003's waypoint switching or a minimum-snap
// fit of its path (nullptr on failure, with q's status and failure set).
std::unique_ptr<ReferenceSource> singleReference(const Scenario& s, const MotionSections& m,
                                                 const VehicleSpec& spec, std::size_t k,
                                                 QuadrotorPlans& q) {
  if (spec.reference) return std::make_unique<PiecewisePolynomialReference>(*spec.reference);
  ParamSet traj = m.trajectory.params;
  if (m.trajectory.mode == TrajectoryMode::Waypoints) {
    const double radius = traj.getDouble("switch_radius", 0.2, 0.01, 100.0);
    traj.requireAllUsed("trajectory mode 'waypoints'");
    return std::make_unique<WaypointReference>(q.plans[k].path.waypoints,
                                               spec.yaw_deg * M_PI / 180.0, radius);
  }
  MinimumSnapResult fit = fitMinimumSnap(s, m.planner, q.airframes[k], q.plans[k], traj);
  if (!fit.success) {
    q.status = PlanStatus::NoTrajectory;
    q.failure = "no feasible trajectory: " + fit.message;
    return nullptr;
  }
  q.plans[k].trajectory_counters = fit.counters;
  return std::make_unique<TrajectoryReference>(std::move(fit.trajectory),
                                               spec.yaw_deg * M_PI / 180.0);
}

}  // namespace

QuadrotorPlans planQuadrotors(const Scenario& s, const MotionSections& m, const WorldModel& world,
                              const std::vector<std::size_t>& vehicles, Planning planning,
                              const RunRequest& request, const RunReporter& report,
                              const TeamRepairs& repairs) {
  QuadrotorPlans q;
  for (std::size_t v : vehicles)
    q.airframes.push_back(believedAirframe(world.vehicles()[v].params, s.model_error));
  if (planning == Planning::Team) {
    planQuadrotorTeam(s, m, world, vehicles, request, report, repairs, q);
  } else {
    planEachQuadrotor(s, m.planner, world, vehicles, request, report, q);
    for (std::size_t k = 0; k < vehicles.size() && q.status == PlanStatus::Ready; ++k)
      q.references.push_back(singleReference(s, m, s.vehicles[vehicles[k]], k, q));
  }
  if (q.status != PlanStatus::Ready) q.references.clear();
  if (!q.plans.empty()) q.trajectory_counters = q.plans.front().trajectory_counters;
  return q;
}

}  // namespace cosim
