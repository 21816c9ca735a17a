#include "run/robot_plans.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/input_error.h"
#include "planning/mapf/mapf_memory_estimate.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/mapf/solution_validator.h"
#include "planning/mapf/timed_paths.h"
#include "run/navigation_driver.h"

namespace cosim {

namespace {

// The speed the plan is timed at: trajectory.max_speed, by default 80 % of the slowest robot's
// top speed (the rest is headroom for the feedback that corrects tracking errors).
double cruiseSpeed(const Scenario& s, const RunSetup& setup, const WorldModel& world) {
  double slowest = std::numeric_limits<double>::infinity();
  for (std::size_t v : setup.robots)
    slowest = std::min(slowest, world.vehicles()[v].drive.max_speed);
  ParamSet p = setup.robot_sections.trajectory.params;
  const double speed = p.getDouble("max_speed", 0.8 * slowest, 1e-3, 100.0);
  p.requireAllUsed("trajectory (ground robots: max_speed only)");
  if (speed > slowest)
    throw InputError(
        s.file, "trajectory.max_speed",
        "faster than the slowest robot's top speed (" + std::to_string(slowest) + " m/s)");
  return speed;
}

double largestRadius(const RunSetup& setup, const WorldModel& world) {
  double r = 0.0;
  for (std::size_t v : setup.robots) r = std::max(r, world.vehicles()[v].params.radius);
  return r;
}

// planner.* of a team plan, and the grid it plans on.
struct TeamGridSettings {
  double resolution = 0.5;
  int connectivity = 4;
  double time_limit = 30.0;
};

TeamGridSettings readTeamGridSettings(const Scenario& s, ParamSet& p) {
  if (s.grid_map.present() && p.has("resolution"))
    throw InputError(s.file, "planner.resolution",
                     "a team plan on world.grid_map uses the map's cells (world.grid_map.cell)");
  TeamGridSettings g;
  g.resolution =
      s.grid_map.present() ? s.grid_map.cell : p.getDouble("resolution", 0.5, 0.01, 100.0);
  g.connectivity = p.getInt("connectivity", 4, 4, 8);
  g.time_limit = p.getDouble("time_limit", 30.0, 0.001, kMaxPlannerTimeLimit);
  if (g.connectivity != 4 && g.connectivity != 8)
    throw InputError(s.file, "planner.connectivity", "must be 4 or 8");
  return g;
}

MapfInstance teamInstance(const Scenario& s, const RunSetup& setup, const TeamGridSettings& g,
                          double radius, double inflation) {
  MapfInstance instance;
  if (s.grid_map.present()) {
    checkRobotsFitGridMap(s, radius, g.connectivity);
    instance.grid = s.grid_map.grid;
  } else {
    instance.grid = robotGrid(s, g.resolution, inflation);
  }
  instance.connectivity = g.connectivity;
  for (std::size_t r : setup.robots) {
    const VehicleSpec& v = s.vehicles[r];
    if (v.waypoints.size() != 1)
      throw InputError(s.file, "vehicles",
                       "a team plan takes one goal per robot ('" + v.name + "' has waypoints)");
    instance.starts.push_back(instance.grid.cellOf(v.start));
    instance.goals.push_back(instance.grid.cellOf(v.goal()));
  }
  checkMapfInstance(instance, s.file);
  return instance;
}

// Every step of the team plan takes the same time (seed 004 §3.6); a diagonal one is the longest.
void timeTeamPaths(const Scenario& s, const RunSetup& setup, const MapfInstance& instance,
                   const std::vector<std::vector<Cell>>& cells, double step_time,
                   RobotPlans& plans) {
  const auto timed = timedMetricPaths(instance.grid, cells, step_time, 0.0);
  for (std::size_t i = 0; i < timed.size(); ++i) {
    GroundTimedPath path;
    const VehicleSpec& v = s.vehicles[setup.robots[i]];
    for (std::size_t k = 0; k < timed[i].size(); ++k)
      // The robot starts where it stands (inside its start cell), not at the cell's centre.
      path.append(kRobotSettleTime + timed[i][k].t,
                  k == 0 ? planarPoint(v.start) : planarPoint(timed[i][k].position));
    // ... and ends on its goal, inside its goal cell, one step after reaching the centre.
    if ((planarPoint(v.goal()) - path.points().back()).norm() > 1e-3)
      path.append(path.endTime() + step_time, planarPoint(v.goal()));
    plans.paths.push_back(std::move(path));
  }
}

// The planner's result as each robot's VehiclePlan (the first carries the team's time).
void teamVehiclePlans(const MapfResult& r, RobotPlans& plans) {
  for (std::size_t i = 0; i < r.paths.size(); ++i) {
    VehiclePlan& p = plans.plans.emplace_back();
    p.success = true;
    p.counters = plans.summary.counters;
    p.params = plans.summary.params;
    p.inflation = plans.summary.inflation;
    p.time_ms = i == 0 ? r.time_ms : 0.0;
  }
}

// Team plan: a multi-robot planner on the planar grid, executed one grid step per step_time. A
// given plan (made by the caller on the same instance) is checked and timed like the planner's.
void planTeam(const Scenario& s, const RunSetup& setup, const WorldModel& world,
              const MapfResult* given, RobotPlans& plans) {
  const PlannerSection& section = setup.robot_sections.planner;
  ParamSet p = section.params;
  const TeamGridSettings g = readTeamGridSettings(s, p);
  const double radius = largestRadius(setup, world);
  plans.summary.inflation = radius + section.margin;
  const MapfInstance instance = teamInstance(s, setup, g, radius, plans.summary.inflation);
  auto planner = makeMapfPlanner(section.name, p, "planner.name");
  checkMapfTableMemory(instance, section.name, s.file);
  for (const auto& [k, v] : p.effective()) plans.summary.params[k] = v;
  MapfQuery query;
  query.instance = &instance;
  query.time_limit_s = g.time_limit;
  query.seed = s.sim.seed;
  const MapfResult r = given ? *given : planner->solve(query, StopToken::untimed());
  plans.summary.time_ms = r.time_ms;
  plans.summary.counters = r.counters;
  const MapfValidation check = validateMapfSolution(instance, r.paths);
  plans.summary.counters["conflicts"] = static_cast<double>(check.conflicts.size());
  // Complete paths with conflicts (independent_astar ignores the other robots) are still driven,
  // and the run fails: the physics shows what the conflicts cost (robot_contacts).
  if (r.paths.size() != instance.starts.size() || !check.problems.empty()) {
    plans.status = PlanStatus::NoPath;
    plans.message = "no team plan: " + (r.message.empty() ? check.problems.front() : r.message);
    return;
  }
  if (!r.success || !check.conflicts.empty()) {
    plans.status = PlanStatus::Conflicting;
    plans.message = "the team plan has " + std::to_string(check.conflicts.size()) + " conflicts";
  }
  plans.summary.counters["sum_of_costs"] = static_cast<double>(sumOfCosts(r.paths));
  plans.summary.counters["makespan"] = makespan(r.paths);
  const double step_time =
      g.resolution * (g.connectivity == 8 ? std::sqrt(2.0) : 1.0) / plans.cruise_speed;
  plans.summary.counters["step_time_s"] = step_time;
  timeTeamPaths(s, setup, instance, r.paths, step_time, plans);
  teamVehiclePlans(r, plans);
}

// One robot per single-agent plan (or the given waypoints), timed at the cruise speed.
void planEach(const Scenario& s, const RunSetup& setup, const WorldModel& world,
              RobotPlans& plans) {
  for (std::size_t v : setup.robots) {
    const VehiclePlan& p = plans.plans.emplace_back(planVehicle(
        s, setup.robot_sections.planner, s.vehicles[v], world.vehicles()[v].params.radius));
    if (!p.success) {
      plans.status = PlanStatus::NoPath;
      plans.message = "no path found for " + s.vehicles[v].name + ": " + p.message;
      break;
    }
    std::vector<Eigen::Vector2d> points;
    for (const auto& w : p.path.waypoints) points.push_back(planarPoint(w));
    plans.paths.push_back(
        GroundTimedPath::atConstantSpeed(points, plans.cruise_speed, kRobotSettleTime));
  }
  plans.summary = summarizeSeparatePlans(plans.plans);
}

// One robot driven by a navigator, which extends its timed path during the drive.
void planNavigation(const Scenario& s, const RunSetup& setup, const WorldModel& world,
                    RobotPlans& plans) {
  const PlannerSection& section = setup.robot_sections.planner;
  const std::string& name = section.name;
  ParamSet p = section.params;
  const double resolution = p.getDouble("resolution", 0.5, 0.01, 100.0);
  auto navigator = makeNavigator(name, p);
  p.requireAllUsed("planner '" + name + "' (in cosim run: resolution and sight)");
  plans.summary.params = p.effective();
  const std::size_t robot = setup.robots.front();
  NavigationWorld nav = navigationWorld(s, world, robot, resolution, plans.cruise_speed,
                                        section.margin, plans.summary.inflation);
  plans.paths.resize(1);
  plans.navigator = std::make_unique<NavigationDriver>(
      std::move(navigator), std::move(nav), s.file, s.vehicles[robot],
      resolution / plans.cruise_speed, plans.paths[0]);
  VehiclePlan& v = plans.plans.emplace_back();
  v.success = true;
  v.params = plans.summary.params;
  v.inflation = plans.summary.inflation;
}

}  // namespace

RobotPlans::RobotPlans() = default;
RobotPlans::RobotPlans(RobotPlans&&) noexcept = default;
RobotPlans& RobotPlans::operator=(RobotPlans&&) noexcept = default;
RobotPlans::~RobotPlans() = default;

OccupancyGrid robotGrid(const Scenario& s, double resolution, double inflation) {
  // The grid's layer sits 0.1 m above the floor, at the height of a small robot's body.
  return OccupancyGrid::fromWorld(s.world, resolution, inflation, true,
                                  s.world.bounds_min.z() + 0.1);
}

RobotPlans planRobots(const Scenario& s, const RunSetup& setup, const WorldModel& world,
                      const MapfResult* given_team_plan) {
  RobotPlans plans;
  plans.cruise_speed = cruiseSpeed(s, setup, world);
  switch (setup.robot_planning) {
    case Planning::Navigator:
      planNavigation(s, setup, world, plans);
      break;
    case Planning::Team:
      planTeam(s, setup, world, given_team_plan, plans);
      break;
    case Planning::Alone:
      planEach(s, setup, world, plans);
      break;
  }
  // The timed plan's corners are rounded so that the robots can follow them within their
  // acceleration limit (GroundTimedPath::setSmoothing).
  const double accel = ParamSet(setup.robot_sections.controller.gains)
                           .getDouble("max_acceleration", 1.0, 1e-3, 100.0);
  for (auto& path : plans.paths) path.setSmoothing(plans.cruise_speed / accel);
  return plans;
}

void checkRobotsFitGridMap(const Scenario& s, double robot_radius, int connectivity) {
  // Robots in neighbouring cells must not touch: centres one cell apart (4-connected), or
  // passing on crossing diagonals, sqrt(2)/2 cell apart at closest (8-connected; see
  // planning/mapf/solution_validator.h).
  const double cell = s.grid_map.cell;
  const double room = (connectivity == 8 ? std::sqrt(2.0) / 4.0 : 0.5) * cell;
  const double need = robot_radius + s.motion.planner.margin;
  if (need > room)
    throw InputError(s.file, "world.grid_map.cell",
                     "robots of radius " + std::to_string(robot_radius) +
                         " m plus planner.margin need cells of at least " +
                         std::to_string(cell * need / room) + " m");
}

}  // namespace cosim
