#include "run/quadrotor_team_planning.h"

#include <algorithm>

#include "core/input_error.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/team/quadrotor_team_planner.h"
#include "run/team_thrust.h"
#include "run/team_tracking_margin.h"

namespace cosim {

namespace {

struct TeamPlannerSettings {
  double time_limit = 30.0;
  double min_separation = kTeamMinSeparation;
};

// planner.* besides the MAPF planner's own parameters (marked used in `p`).
TeamPlannerSettings readTeamPlannerSettings(ParamSet& p) {
  TeamPlannerSettings s;
  s.time_limit = p.getDouble("time_limit", s.time_limit, 0.001, kMaxPlannerTimeLimit);
  s.min_separation = p.getDouble("min_separation", s.min_separation, 1.0, 10.0);
  return s;
}

std::vector<TeamAgent> teamAgents(const Scenario& s, const PlannerSection& planner,
                                  const WorldModel& world,
                                  const std::vector<std::size_t>& vehicles) {
  std::vector<TeamAgent> agents;
  for (std::size_t v : vehicles) {
    const VehicleSpec& spec = s.vehicles[v];
    if (spec.waypoints.size() != 1)
      throw InputError(
          s.file, "vehicles[" + std::to_string(v) + "]",
          "a team plan takes one goal per vehicle ('" + spec.name + "' has waypoints)");
    const QuadrotorParams& q = world.vehicles()[v].params;
    TeamAgent a;
    a.start = spec.start;
    a.goal = spec.goal();
    a.separation =
        planner.separation.value_or(SeparationEllipsoid{q.separation_radius, q.separation_height});
    a.inflation = q.radius + planner.margin;
    // As for a single quadrotor's trajectory: half the margin is the budget for tracking error.
    a.clearance = q.radius + 0.5 * planner.margin;
    agents.push_back(a);
  }
  return agents;
}

std::vector<VehiclePlan> vehiclePlans(const TeamPlan& team, const TeamPlanningProblem& problem,
                                      const std::map<std::string, std::string>& params) {
  std::vector<VehiclePlan> plans(problem.agents.size());
  for (std::size_t i = 0; i < plans.size(); ++i) {
    VehiclePlan& p = plans[i];
    p.success = team.success;
    p.message = team.message;
    p.inflation = problem.agents[i].inflation;
    p.counters = team.counters;
    p.params = params;
    if (i < team.points.size()) p.path.waypoints = team.points[i];
    p.via_indices.push_back(p.path.waypoints.empty() ? 0 : p.path.waypoints.size() - 1);
  }
  if (!plans.empty()) plans.front().time_ms = team.time_ms;  // the team is planned once
  return plans;
}

// Thrust is checked every this many seconds of the plan (its pieces last a step: a second or more).
constexpr double kThrustCheckInterval = 0.05;
// Each slowing stretches the step time by this factor (the trajectories' accelerations fall with
// its square), at most this many times.
constexpr double kThrustStretch = 1.2;
constexpr int kMaxThrustStretches = 6;

// The team planned again, slower, until no member asks for more than team.max_thrust_fraction of
// its thrust (the downwash from above counted); the plan fails if that takes more slowings than
// allowed. Returns the plan's thrust peak.
TeamThrustPeak slowUntilThrustFeasible(const Scenario& s, const std::vector<std::size_t>& vehicles,
                                       const std::vector<QuadrotorParams>& airframes,
                                       MapfPlanner& planner, TeamPlanningProblem& problem,
                                       TeamPlan& team) {
  TeamThrustPeak peak;
  double time_ms = team.time_ms;
  for (int k = 0; team.success; ++k) {
    peak = peakTeamThrust(team.trajectories, airframes, kThrustCheckInterval);
    if (peak.fraction <= s.team.max_thrust_fraction) break;
    if (k == kMaxThrustStretches) {
      team.success = false;
      team.message = s.vehicles[vehicles[peak.member]].name + "'s trajectory asks for " +
                     std::to_string(peak.fraction) + " of its thrust at " + std::to_string(peak.t) +
                     " s (downwash from above counted), more than "
                     "team.max_thrust_fraction " +
                     std::to_string(s.team.max_thrust_fraction) + " even " +
                     std::to_string(problem.step_stretch) + " times slower";
      break;
    }
    problem.step_stretch *= kThrustStretch;
    team = planQuadrotorTeam(problem, planner);
    time_ms += team.time_ms;
  }
  team.time_ms = time_ms;
  return peak;
}

}  // namespace

void checkQuadrotorTeamPlanner(const Scenario& scenario) {
  ParamSet p = scenario.motion.planner.params;
  readTeamPlannerSettings(p);
  makeMapfPlanner(scenario.motion.planner.name, p, "planner.name");
}

QuadrotorTeamFlight planQuadrotorTeamFlight(const Scenario& s, const MotionSections& m,
                                            const WorldModel& world,
                                            const std::vector<std::size_t>& vehicles,
                                            const std::vector<QuadrotorParams>& airframes,
                                            const RunRequest& request, const TeamRepairs& repairs) {
  ParamSet p = m.planner.params;
  const TeamPlannerSettings settings = readTeamPlannerSettings(p);
  auto planner = makeMapfPlanner(m.planner.name, p, "planner.name");
  ParamSet t = m.trajectory.params;
  TeamPlanningProblem problem;
  problem.world = &s.world;
  problem.agents = teamAgents(s, m.planner, world, vehicles);
  // Grown by what the controller's tracking error takes off in flight, and by what a
  // verification flight found missing.
  problem.min_separation = std::max(teamSeparationFor(m.controller.name, settings.min_separation),
                                    repairs.min_separation);
  problem.max_speed = t.getDouble("max_speed", kTeamMaxSpeed, 0.01, 100.0);
  problem.max_acceleration = t.getDouble("max_acceleration", kTeamMaxAcceleration, 0.01, 100.0);
  t.requireAllUsed("trajectory of a quadrotor team (max_speed, max_acceleration)");
  problem.time_limit_s = settings.time_limit;
  problem.seed = s.sim.seed;
  problem.stop = request.interrupt;
  problem.rest_steps = repairs.rest_steps;
  problem.step_stretch = repairs.step_stretch;
  if (request.observer)
    problem.progress = [&request](const std::string& line) {
      RunEvent e;
      e.kind = RunEventKind::Message;
      e.stage = RunStage::Plan;
      e.text = line;
      request.observer(e);
    };

  // A start or goal the grid cannot hold, a planner without 3D grids: InputError, which the
  // prepare stage places in the scenario's file (run/prepared_run.h).
  TeamPlan team = planQuadrotorTeam(problem, *planner);
  const TeamThrustPeak thrust =
      slowUntilThrustFeasible(s, vehicles, airframes, *planner, problem, team);
  std::map<std::string, std::string> params = p.effective();
  params["margin"] = std::to_string(m.planner.margin);
  params["min_separation"] = std::to_string(problem.min_separation);
  if (m.planner.separation) {
    params["separation.radius"] = std::to_string(m.planner.separation->radius);
    params["separation.height"] = std::to_string(m.planner.separation->height);
  }
  team.counters["planned_peak_thrust_fraction"] = thrust.fraction;
  team.counters["step_stretch"] = problem.step_stretch;
  QuadrotorTeamFlight flight;
  flight.plans = vehiclePlans(team, problem, params);
  flight.success = team.success;
  if (!team.success) flight.failure = "no path found: " + team.message;
  flight.trajectories = std::move(team.trajectories);
  return flight;
}

}  // namespace cosim
