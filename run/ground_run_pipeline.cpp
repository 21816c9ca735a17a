#include "run/ground_run_pipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>

#include "control/ground_feedback_linearization.h"
#include "control/ground_velocity_tracker.h"
#include "core/output_files.h"
#include "run/quadrotor_pilots.h"
#include "run/quadrotor_team_planning.h"
#include "run/run_files.h"
#include "run/scenario_planning.h"
#include "core/input_error.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/mapf/solution_validator.h"
#include "planning/mapf/timed_paths.h"
#include "planning/navigation/d_star_lite.h"
#include "planning/navigation/robot_navigation_ant.h"
#include "planning/planner_registry.h"
#include "render/progress_bar.h"
#include "render/run_outputs.h"
#include "sim/flight_metrics.h"
#include "sim/ground_simulation.h"
#include "core/json_writer.h"
#include "sim/moving_obstacle_motion.h"
#include "sim/run_log_io.h"
#include "sim/uav_separation_metrics.h"
#include "sim/world_model.h"

namespace cosim {

namespace {

// Robots settle on their wheels before the plan's clock starts.
constexpr double kSettleTime = 0.2;  // s

bool isNavigatorName(const std::string& name) {
  return name == "rna" || name == "wf_rna" || name == "d_star_lite";
}

Eigen::Vector2d xy(const Eigen::Vector3d& p) {
  return p.head<2>();
}
Eigen::Vector3d onFloor(const Eigen::Vector2d& p) {
  return {p.x(), p.y(), 0.0};
}

// What the planning stage hands the simulation.
struct GroundPlan {
  bool success = false;
  std::string message;
  std::string conflicts_message;       // driven anyway, but the run fails
  std::vector<GroundTimedPath> paths;  // one per robot
  double time_ms = 0.0;
  double inflation = 0.0;
  std::map<std::string, double> counters;
  std::map<std::string, std::string> params;
};

// The speed the plan is timed at: trajectory.max_speed, by default 80 % of the slowest robot's
// top speed (the rest is headroom for the feedback that corrects tracking errors).
double cruiseSpeed(Scenario& s, const WorldModel& world) {
  double slowest = std::numeric_limits<double>::infinity();
  for (const auto& v : world.vehicles())
    if (v.ground) slowest = std::min(slowest, v.drive.max_speed);
  ParamSet p = s.trajectory_params;
  const double speed = p.getDouble("max_speed", 0.8 * slowest, 1e-3, 100.0);
  p.requireAllUsed("trajectory (ground robots: max_speed only)");
  if (speed > slowest)
    throw InputError(
        s.file, "trajectory.max_speed",
        "faster than the slowest robot's top speed (" + std::to_string(slowest) + " m/s)");
  return speed;
}

// Of the ground robots (quadrotors fly over the team's grid).
double largestRadius(const WorldModel& world) {
  double r = 0.0;
  for (const auto& v : world.vehicles())
    if (v.ground) r = std::max(r, v.params.radius);
  return r;
}

// The ground robots' handles, in the order of the scenario's robots.
std::vector<const VehicleHandles*> robotHandles(const WorldModel& world) {
  std::vector<const VehicleHandles*> robots;
  for (const auto& v : world.vehicles())
    if (v.ground) robots.push_back(&v);
  return robots;
}

OccupancyGrid planarGrid(const Scenario& s, double resolution, double inflation) {
  // The grid's layer sits 0.1 m above the floor, at the height of a small robot's body.
  return OccupancyGrid::fromWorld(s.world, resolution, inflation, true,
                                  s.world.bounds_min.z() + 0.1);
}

// Team plan: a multi-robot planner on the planar grid, executed one grid step per step_time.
GroundPlan planTeam(Scenario& s, const WorldModel& world, double speed) {
  GroundPlan plan;
  ParamSet p = s.planner_params;
  if (s.grid_map.present() && p.has("resolution"))
    throw InputError(s.file, "planner.resolution",
                     "a team plan on world.grid_map uses the map's cells (world.grid_map.cell)");
  const double resolution =
      s.grid_map.present() ? s.grid_map.cell : p.getDouble("resolution", 0.5, 0.01, 100.0);
  const int connectivity = p.getInt("connectivity", 4, 4, 8);
  const double time_limit = p.getDouble("time_limit", 30.0, 0.001, kMaxPlannerTimeLimit);
  if (connectivity != 4 && connectivity != 8)
    throw InputError(s.file, "planner.connectivity", "must be 4 or 8");
  plan.inflation = largestRadius(world) + s.planner_margin;
  MapfInstance instance;
  if (s.grid_map.present()) {
    checkRobotsFitGridMap(s, largestRadius(world), connectivity);
    instance.grid = s.grid_map.grid;
  } else {
    instance.grid = planarGrid(s, resolution, plan.inflation);
  }
  instance.connectivity = connectivity;
  for (const VehicleSpec& v : s.vehicles) {
    if (v.waypoints.size() != 1)
      throw InputError(s.file, "vehicles",
                       "a team plan takes one goal per robot ('" + v.name + "' has waypoints)");
    instance.starts.push_back(instance.grid.cellOf(v.start));
    instance.goals.push_back(instance.grid.cellOf(v.goal()));
  }
  checkMapfInstance(instance, s.file);
  auto planner = makeMapfPlanner(s.planner_name, p, "planner.name");
  for (const auto& [k, v] : p.effective()) plan.params[k] = v;
  MapfQuery query;
  query.instance = &instance;
  query.time_limit_s = time_limit;
  query.seed = s.sim.seed;
  const MapfResult r = planner->solve(query);
  plan.time_ms = r.time_ms;
  plan.counters = r.counters;
  const MapfValidation check = validateMapfSolution(instance, r.paths);
  plan.counters["conflicts"] = static_cast<double>(check.conflicts.size());
  // Complete paths with conflicts (independent_astar ignores the other robots) are still driven,
  // and the run fails: the physics shows what the conflicts cost (robot_contacts).
  if (r.paths.size() != instance.starts.size() || !check.problems.empty()) {
    plan.message = "no team plan: " + (r.message.empty() ? check.problems.front() : r.message);
    return plan;
  }
  if (!r.success || !check.conflicts.empty())
    plan.conflicts_message =
        "the team plan has " + std::to_string(check.conflicts.size()) + " conflicts";
  plan.counters["sum_of_costs"] = static_cast<double>(sumOfCosts(r.paths));
  plan.counters["makespan"] = makespan(r.paths);
  // Every step takes the same time (seed 004 §3.6); a diagonal one is the longest.
  const double step_time = resolution * (connectivity == 8 ? std::sqrt(2.0) : 1.0) / speed;
  plan.counters["step_time_s"] = step_time;
  const auto timed = timedMetricPaths(instance.grid, r.paths, step_time, 0.0);
  for (std::size_t i = 0; i < timed.size(); ++i) {
    GroundTimedPath path;
    const VehicleSpec& v = s.vehicles[i];
    for (std::size_t k = 0; k < timed[i].size(); ++k)
      // The robot starts where it stands (inside its start cell), not at the cell's centre.
      path.append(kSettleTime + timed[i][k].t, k == 0 ? xy(v.start) : xy(timed[i][k].position));
    // ... and ends on its goal, inside its goal cell, one step after reaching the centre.
    if ((xy(v.goal()) - path.points().back()).norm() > 1e-3)
      path.append(path.endTime() + step_time, xy(v.goal()));
    plan.paths.push_back(std::move(path));
  }
  plan.success = true;
  return plan;
}

// One robot per single-agent plan (or the given waypoints), timed at the cruise speed.
GroundPlan planEach(Scenario& s, const WorldModel& world, double speed) {
  GroundPlan plan;
  const auto robots = robotHandles(world);
  for (std::size_t v = 0; v < s.vehicles.size(); ++v) {
    const VehiclePlan p = planVehicle(s, s.vehicles[v], robots[v]->params.radius, s.planner_params);
    plan.time_ms += p.time_ms;
    for (const auto& [k, c] : p.counters) plan.counters[k] += c;
    plan.params = p.params;
    plan.inflation = p.inflation;
    if (!p.success) {
      plan.message = "no path found for " + s.vehicles[v].name + ": " + p.message;
      return plan;
    }
    std::vector<Eigen::Vector2d> points;
    for (const auto& w : p.path.waypoints) points.push_back(xy(w));
    plan.paths.push_back(GroundTimedPath::atConstantSpeed(points, speed, kSettleTime));
  }
  plan.success = true;
  return plan;
}

std::unique_ptr<Navigator> makeNavigator(const std::string& name, ParamSet& p) {
  // The navigators' main parameter; their other parameters keep their defaults here.
  const int sight = p.getInt("sight", 10, 1, 1000);
  if (name == "d_star_lite") {
    DStarLiteParams d;
    d.sight = sight;
    return std::make_unique<DStarLite>(d);
  }
  RnaParams r;
  r.sight = sight;
  r.wave_front = name == "wf_rna";
  return std::make_unique<RobotNavigationAnt>(r);
}

// Drives one robot with a navigator: whenever the robot's commanded step is over, it asks the
// navigator for the next cell (from the robot's measured cell) and extends the timed path by one
// step. Navigation time runs in robot steps: one cell per `tau` seconds (seed 000 §4.2.3).
class NavigationDriver {
 public:
  NavigationDriver(std::unique_ptr<Navigator> navigator, NavigationWorld world,
                   const std::string& file, const VehicleSpec& v, double tau, GroundTimedPath& path)
      : navigator_(std::move(navigator)),
        world_(std::move(world)),
        goal_(v.goal()),
        tau_(tau),
        path_(path) {
    const OccupancyGrid& g = world_.grid();
    commanded_ = g.cellOf({v.start.x(), v.start.y(), g.origin().z() + 0.5 * g.cellSize()});
    goal_cell_ = g.cellOf({goal_.x(), goal_.y(), g.origin().z() + 0.5 * g.cellSize()});
    if (g.blocked(commanded_) || g.blocked(goal_cell_))
      throw InputError(
          file, "vehicles",
          "'" + v.name + "': start or goal lies in a blocked cell of the navigation grid");
    navigator_->reset(world_, commanded_, goal_cell_, 1);
    path_.append(0.0, xy(v.start));
    path_.append(kSettleTime, xy(v.start));
    executed_.push_back(onFloor(xy(v.start)));
  }

  // before_control: false when the navigator gives up. The smoothed reference looks `smoothing`
  // seconds ahead, so the next step is decided that early, for the robot at its commanded cell
  // at the time it is due there (its measured deviation from the plan is in the metrics).
  bool update(double t) {
    if (done_ || t + path_.smoothing() + 1e-9 < path_.endTime()) return true;
    const OccupancyGrid& g = world_.grid();
    const Cell at = commanded_;
    t = path_.endTime();
    if (at == goal_cell_) {
      path_.append(t + tau_, xy(goal_));
      executed_.push_back(onFloor(xy(goal_)));
      done_ = true;
      return true;
    }
    const auto start = std::chrono::steady_clock::now();
    const NavigationDecision d = navigator_->decide(at, navigationTime(t));
    plan_ms_ +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ++decisions_;
    replans_ += d.replans;
    if (d.give_up) {
      message_ = d.note;
      return false;
    }
    const bool wait = d.next == at;
    waits_ += wait ? 1 : 0;
    const bool diagonal = d.next.x != at.x && d.next.y != at.y;
    path_.append(t + tau_ * (diagonal ? std::sqrt(2.0) : 1.0), xy(g.cellCenter(d.next)));
    if (!wait) executed_.push_back(onFloor(xy(g.cellCenter(d.next))));
    commanded_ = d.next;
    return true;
  }

  double navigationTime(double t) const { return std::max(0.0, t - kSettleTime) / tau_; }
  Eigen::Vector2d obstacle(std::size_t i, double t) const {
    return xy(world_.obstacleCentre(i, navigationTime(t)));
  }
  const std::vector<Eigen::Vector3d>& executed() const { return executed_; }
  std::map<std::string, double> counters() const {
    return {{"decisions", decisions_},
            {"waits", waits_},
            {"replans", replans_},
            {"mean_plan_ms", decisions_ ? plan_ms_ / decisions_ : 0.0}};
  }
  const std::string& message() const { return message_; }

 private:
  std::unique_ptr<Navigator> navigator_;
  NavigationWorld world_;
  Eigen::Vector3d goal_;
  double tau_;
  GroundTimedPath& path_;
  Cell commanded_, goal_cell_;
  bool done_ = false;
  double decisions_ = 0, waits_ = 0, replans_ = 0, plan_ms_ = 0.0;
  std::vector<Eigen::Vector3d> executed_;
  std::string message_;
};

// The navigator's world: the static map as a planar grid, the moving obstacles with their path
// points snapped to cell centres (the navigator's obstacles live on the grid; the physical ones
// then follow the very same trajectories), speeds in cells per robot step.
NavigationWorld navigationWorld(Scenario& s, const WorldModel& world, double resolution,
                                double speed, double& inflation) {
  const double robot = robotHandles(world).front()->params.radius;
  inflation = robot + s.planner_margin;
  OccupancyGrid grid = planarGrid(s, resolution, inflation);
  std::vector<MovingObstacle> obstacles;
  for (std::size_t i = 0; i < s.moving_obstacles.size(); ++i) {
    const MovingObstacleSpec& o = s.moving_obstacles[i];
    // Two one-cell squares that do not overlap keep their centres a cell apart, so the bodies
    // cannot touch when they fit in a cell together.
    if (movingObstacleFootprintRadius(o) + robot >= resolution)
      throw InputError(s.file, "world.moving_obstacles[" + std::to_string(i) + "]",
                       "footprint radius + robot radius (" + std::to_string(robot) +
                           " m) must be below the navigation grid's resolution (" +
                           std::to_string(resolution) + " m)");
    std::vector<Cell> cells;
    for (const auto& p : o.path)
      cells.push_back(grid.cellOf({p.x(), p.y(), grid.origin().z() + 0.5 * resolution}));
    obstacles.emplace_back(
        cells, o.speed / speed,
        o.loop ? MovingObstacle::Mode::Loop : MovingObstacle::Mode::BackAndForth);
  }
  return NavigationWorld(std::move(grid), std::move(obstacles));
}

std::unique_ptr<GroundController> makeGroundController(ParamSet& gains, const VehicleHandles& h) {
  GroundMotionLimits limits;
  limits.max_speed = h.drive.max_speed;
  limits.max_yaw_rate = h.drive.max_yaw_rate;
  limits.max_acceleration = gains.getDouble("max_acceleration", 1.0, 1e-3, 100.0);
  limits.max_yaw_acceleration = gains.getDouble("max_yaw_acceleration", 4.0, 1e-3, 1000.0);
  if (h.drive.kind == GroundDrive::Kind::Holonomic) {
    GroundVelocityTrackerGains g;
    g.k_position = gains.getDouble("k_position", g.k_position, 1e-3, 100.0);
    g.k_yaw = gains.getDouble("k_yaw", g.k_yaw, 1e-3, 100.0);
    return std::make_unique<GroundVelocityTracker>(limits, g);
  }
  GroundFeedbackLinearizationParams p;
  p.b = gains.getDouble("b", p.b, 1e-3, 10.0);
  p.k = gains.getDouble("k", p.k, 1e-3, 100.0);
  p.wheel_separation = h.drive.wheel_separation;
  return std::make_unique<GroundFeedbackLinearization>(limits, p);
}

// Team figures from the log: contacts by kind, closest approaches, deviation, arrivals.
struct TeamMetrics {
  int robot_contacts = 0, obstacle_contacts = 0, moving_obstacle_contacts = 0;
  int robot_uav_contacts = 0, uav_contacts = 0;  // a quadrotor with a robot, with a quadrotor
  double min_robot_distance_m = std::numeric_limits<double>::infinity();  // surface to surface
  double min_moving_obstacle_distance_m = std::numeric_limits<double>::infinity();
};

// `ground[v]`: log.vehicles[v] is a ground robot (else a quadrotor).
TeamMetrics teamMetrics(const RunLog& log, const std::vector<bool>& ground) {
  TeamMetrics t;
  for (std::size_t v = 0; v < log.vehicles.size(); ++v) {
    for (const ContactEvent& c : log.vehicles[v].collisions) {
      bool vehicle = false;
      for (std::size_t w = 0; w < log.vehicles.size(); ++w) {
        if (w == v || c.other.rfind(log.vehicles[w].name + "/", 0) != 0) continue;
        vehicle = true;
        if (w < v) continue;  // each touching pair is booked by both vehicles
        int& count = ground[v] && ground[w]     ? t.robot_contacts
                     : !ground[v] && !ground[w] ? t.uav_contacts
                                                : t.robot_uav_contacts;
        ++count;
      }
      if (vehicle) continue;
      if (c.other.rfind("moving", 0) == 0)
        ++t.moving_obstacle_contacts;
      else
        ++t.obstacle_contacts;
    }
  }
  // Samples are logged at the same instants for every vehicle and obstacle. Closest approaches
  // are between robots' footprints (quadrotors fly over them).
  for (std::size_t v = 0; v < log.vehicles.size(); ++v) {
    if (!ground[v]) continue;
    const auto& a = log.vehicles[v];
    for (std::size_t k = 0; k < a.samples.size(); ++k) {
      for (std::size_t w = v + 1; w < log.vehicles.size(); ++w) {
        const auto& b = log.vehicles[w];
        if (ground[w] && k < b.samples.size())
          t.min_robot_distance_m = std::min(
              t.min_robot_distance_m,
              (a.samples[k].pos - b.samples[k].pos).head<2>().norm() - a.radius - b.radius);
      }
      for (const auto& o : log.moving_obstacles)
        if (k < o.pos.size())
          t.min_moving_obstacle_distance_m =
              std::min(t.min_moving_obstacle_distance_m,
                       (a.samples[k].pos - o.pos[k]).head<2>().norm() - a.radius - o.radius);
    }
  }
  return t;
}

// The quadrotors' view of a scenario with ground robots: the `aerial` sections in place of the
// top-level planner, trajectory and controller, which drive the robots.
Scenario aerialScenario(const Scenario& s) {
  Scenario a = s;
  a.planner_name = s.aerial.planner_name;
  a.planner_params = s.aerial.planner_params;
  a.planner_margin = s.aerial.planner_margin;
  a.planner_separation = s.aerial.planner_separation;
  a.trajectory_mode = s.aerial.trajectory_mode;
  a.trajectory_params = s.aerial.trajectory_params;
  a.controller_name = s.aerial.controller_name;
  a.controller_drag_compensation = s.aerial.controller_drag_compensation;
  a.controller_gains = s.aerial.controller_gains;
  return a;
}

}  // namespace

void checkRobotsFitGridMap(const Scenario& s, double robot_radius, int connectivity) {
  // Robots in neighbouring cells must not touch: centres one cell apart (4-connected), or
  // passing on crossing diagonals, sqrt(2)/2 cell apart at closest (8-connected; see
  // planning/mapf/solution_validator.h).
  const double cell = s.grid_map.cell;
  const double room = (connectivity == 8 ? std::sqrt(2.0) / 4.0 : 0.5) * cell;
  const double need = robot_radius + s.planner_margin;
  if (need > room)
    throw InputError(s.file, "world.grid_map.cell",
                     "robots of radius " + std::to_string(robot_radius) +
                         " m plus planner.margin need cells of at least " +
                         std::to_string(cell * need / room) + " m");
}

void checkRunPlanners(const Scenario& s) {
  const auto single = [&s](const std::string& name, ParamSet p, const std::string& key) {
    if (name.empty()) return;
    p.getDouble("time_limit", 30.0, 0.001, kMaxPlannerTimeLimit);  // read by planVehicle
    makePlanner(name, p, key);
  };
  if (!isGroundRun(s))
    return isMapfPlanner(s.planner_name)
               ? checkQuadrotorTeamPlanner(s)
               : single(s.planner_name, s.planner_params, "key planner.name");
  const std::string& name = s.planner_name;
  ParamSet p = s.planner_params;
  if (isNavigatorName(name)) {
    p.getDouble("resolution", 0.5, 0.01, 100.0);
    makeNavigator(name, p);
    p.requireAllUsed("planner '" + name + "' (in cosim run: resolution and sight)");
  } else if (isMapfPlanner(name)) {
    if (!s.grid_map.present()) p.getDouble("resolution", 0.5, 0.01, 100.0);
    p.getInt("connectivity", 4, 4, 8);
    p.getDouble("time_limit", 30.0, 0.001, kMaxPlannerTimeLimit);
    makeMapfPlanner(name, p, "planner.name");
  } else {
    single(name, p, "key planner.name");
  }
  if (!s.aerial.planner_name.empty()) {
    if (!PlannerRegistry::instance().find(s.aerial.planner_name))
      throw InputError(s.file, "aerial.planner.name",
                       "unknown single-agent planner '" + s.aerial.planner_name + "'");
    single(s.aerial.planner_name, s.aerial.planner_params, "key aerial.planner.name");
  }
}

bool isGroundRun(const Scenario& s) {
  if (!s.moving_obstacles.empty()) return true;
  return std::any_of(s.vehicles.begin(), s.vehicles.end(),
                     [](const VehicleSpec& v) { return v.ground; });
}

RunSummary executeGroundRun(Scenario& scenario, const RunRequest& request) {
  // The ground robots (driven by the top-level planner, trajectory and controller) and the
  // quadrotors flying over them (the `aerial` sections), as indices into scenario.vehicles.
  std::vector<std::size_t> robot_ids, quadrotor_ids;
  for (std::size_t v = 0; v < scenario.vehicles.size(); ++v)
    (scenario.vehicles[v].ground ? robot_ids : quadrotor_ids).push_back(v);
  if (robot_ids.empty())
    throw InputError(scenario.file, "world.moving_obstacles",
                     "moving obstacles need ground robots (omni_base, diff_drive or a URDF): "
                     "quadrotors do not sense them");
  if (scenario.disturbances.any() && quadrotor_ids.empty())
    throw InputError(scenario.file, "disturbances",
                     "wind, rotor drag and ground effect act on quadrotors; this scenario has "
                     "none (ground robots feel no disturbances)");
  RunSummary summary;
  const WorldModel world = WorldModel::build(scenario);
  if (stopRequestedFor(request)) return interruptedRun();
  Scenario robots = scenario;
  robots.vehicles.clear();
  for (std::size_t v : robot_ids) robots.vehicles.push_back(scenario.vehicles[v]);
  const double speed = cruiseSpeed(robots, world);
  const std::string& name = scenario.planner_name;

  // 1. Plan.
  GroundPlan plan;
  std::unique_ptr<NavigationDriver> driver;
  if (isNavigatorName(name)) {
    if (robots.vehicles.size() != 1)
      throw InputError(scenario.file, "planner.name", "navigators (" + name + ") drive one robot");
    ParamSet p = robots.planner_params;
    const double resolution = p.getDouble("resolution", 0.5, 0.01, 100.0);
    auto navigator = makeNavigator(name, p);
    p.requireAllUsed("planner '" + name + "' (in cosim run: resolution and sight)");
    plan.params = p.effective();
    NavigationWorld nav = navigationWorld(robots, world, resolution, speed, plan.inflation);
    plan.paths.resize(1);
    driver =
        std::make_unique<NavigationDriver>(std::move(navigator), std::move(nav), robots.file,
                                           robots.vehicles[0], resolution / speed, plan.paths[0]);
    plan.success = true;
  } else if (isMapfPlanner(name)) {
    plan = planTeam(robots, world, speed);
  } else {
    plan = planEach(robots, world, speed);
  }
  // Each quadrotor: its own path, reference and flight controller (the `aerial` sections).
  Scenario air = aerialScenario(scenario);
  if (!air.planner_name.empty() && !PlannerRegistry::instance().find(air.planner_name)) {
    std::string known;
    for (const auto& e : PlannerRegistry::instance().entries())
      known += (known.empty() ? "" : ", ") + e.name;
    throw InputError(
        scenario.file, "aerial.planner.name",
        "unknown single-agent planner '" + air.planner_name + "' (known: " + known + ")");
  }
  QuadrotorPilots quadrotors;
  quadrotors.ready = true;
  if (!quadrotor_ids.empty())  // also when the robots have no plan: bad input is exit 2
    quadrotors = prepareQuadrotorPilots(air, world, quadrotor_ids, request);
  const bool drive = plan.success && quadrotors.ready;
  // A stop during planning ends the planners early: their "no plan" is not a result.
  if (stopRequestedFor(request)) return interruptedRun();

  // The timed plan's corners are rounded so that the robots can follow them within their
  // acceleration limit (GroundTimedPath::setSmoothing).
  const double accel =
      ParamSet(scenario.controller_gains).getDouble("max_acceleration", 1.0, 1e-3, 100.0);
  for (auto& path : plan.paths) path.setSmoothing(speed / accel);

  // 2. Controllers, and 3. drive (and fly).
  const auto handles = robotHandles(world);
  std::vector<std::unique_ptr<GroundController>> controllers;
  std::vector<GroundPilot> pilots;
  RunLog log;
  if (drive) {
    for (std::size_t v = 0; v < robots.vehicles.size(); ++v) {
      ParamSet gains = scenario.controller_gains;
      controllers.push_back(makeGroundController(gains, *handles[v]));
      gains.requireAllUsed("controller.gains (ground robots)");
      GroundPilot pilot;
      pilot.controller = controllers.back().get();
      pilot.path = &plan.paths[v];
      pilot.yaw = robots.vehicles[v].yaw_deg * M_PI / 180.0;
      pilot.goal = onFloor(xy(robots.vehicles[v].goal()));
      for (const auto& p : plan.paths[v].points()) pilot.planned_path.push_back(onFloor(p));
      pilots.push_back(pilot);
    }
    GroundSimOptions options;
    options.settings = scenario.sim;
    options.interrupt = request.interrupt;
    if (driver) {
      options.before_control = [&driver](double t, const std::vector<PlanarState>&) {
        return driver->update(t);
      };
      options.obstacle_position = [&driver](std::size_t i, double t) {
        return driver->obstacle(i, t);
      };
    }
    // Progress in simulated seconds against the plan's makespan (the run ends about then).
    double planned_end = 0.0;
    for (const auto& path : plan.paths) planned_end = std::max(planned_end, path.endTime());
    ProgressBar drive_progress("driving (simulated s)", static_cast<int>(std::ceil(planned_end)),
                               request.progress);
    options.before_control = [&drive_progress, navigate = options.before_control](
                                 double t, const std::vector<PlanarState>& states) {
      drive_progress.update(static_cast<int>(t));
      return navigate ? navigate(t, states) : true;
    };
    if (request.progress)
      std::cerr << "cosim: driving " << pilots.size() << " ground robot(s)"
                << (quadrotor_ids.empty()
                        ? std::string()
                        : " under " + std::to_string(quadrotor_ids.size()) + " quadrotor(s)")
                << std::endl;
    log = simulateGround(world, scenario, pilots, quadrotors.pilots, options);
    if (driver) {
      log.vehicles[robot_ids[0]].planned_path = driver->executed();
      plan.counters = driver->counters();
    }
  } else {
    for (const VehicleSpec& v : scenario.vehicles) {
      VehicleLog& vl = log.vehicles.emplace_back();
      vl.name = v.name;
      vl.goal = v.goal();
    }
    log.end_reason = "no_path";
  }
  if (log.end_reason == "interrupted") {
    summary.status = 1;
    summary.message = "interrupted";
    return summary;
  }

  // 4. Evaluate, from the log. The team figures are the robots' (plan-vs-executed); the
  // quadrotors have their flight metrics; arrival, contacts and clearance count everyone.
  summary.sim_speed_x = log.wall_time > 0 ? log.sim_time / log.wall_time : 0.0;
  std::vector<bool> ground(scenario.vehicles.size());
  for (std::size_t v = 0; v < ground.size(); ++v) ground[v] = scenario.vehicles[v].ground;
  const TeamMetrics team = teamMetrics(log, ground);
  bool reached = true;
  const int collisions = team.robot_contacts + team.obstacle_contacts +
                         team.moving_obstacle_contacts + team.robot_uav_contacts +
                         team.uav_contacts;
  double planned = 0, flown = 0, sum_sq = 0, max_error = 0,
         clearance = std::numeric_limits<double>::infinity();
  double makespan_s = 0.0, sum_arrivals = 0.0, planned_makespan = 0.0;
  double uav_sum_sq = 0.0, uav_max_error = 0.0, uav_saturation = 0.0;
  std::size_t samples = 0, uav_samples = 0;
  std::vector<JsonObject> per_vehicle;
  for (std::size_t v = 0, r = 0; v < log.vehicles.size(); ++v) {
    const VehicleLog& vl = log.vehicles[v];
    const double n = static_cast<double>(vl.samples.size());
    const double arrival = vl.arrival_time;
    if (!ground[v]) {
      const FlightMetrics m =
          computeFlightMetrics(vl, scenario.world, air.trajectory_mode != "waypoints");
      summary.metrics.push_back(m);
      reached = reached && m.reached_goal;
      clearance = std::min(clearance, m.min_clearance_m);
      uav_sum_sq += m.rmse_m * m.rmse_m * n;
      uav_samples += vl.samples.size();
      uav_max_error = std::max(uav_max_error, m.max_error_m);
      uav_saturation = std::max(uav_saturation, longestSaturation(vl));
      JsonObject j = flightMetricsJson(m);
      j.add("name", vl.name)
          .add("model", scenario.vehicles[v].model)
          .add("kind", "quadrotor")
          .add("arrival_time_s", arrival)
          .add("radius_m", vl.radius);
      per_vehicle.push_back(j);
      continue;
    }
    const FlightMetrics m = computeFlightMetrics(vl, scenario.world, true);
    summary.metrics.push_back(m);
    reached = reached && m.reached_goal;
    planned += m.planned_length_m;
    flown += m.flown_length_m;
    sum_sq += m.rmse_m * m.rmse_m * n;
    samples += vl.samples.size();
    max_error = std::max(max_error, m.max_error_m);
    clearance = std::min(clearance, m.min_clearance_m);
    makespan_s = std::max(makespan_s, arrival);
    sum_arrivals += std::max(arrival, 0.0);
    const double planned_arrival = drive ? plan.paths[r].endTime() : -1.0;
    planned_makespan = std::max(planned_makespan, planned_arrival);
    ++r;
    JsonObject j;
    j.add("name", vl.name)
        .add("model", scenario.vehicles[v].model)
        .add("kind", "ground_robot")
        .add("reached_goal", m.reached_goal)
        .add("arrival_time_s", arrival)
        .add("planned_arrival_s", planned_arrival)
        .add("contacts", m.collisions)
        .add("planned_length_m", m.planned_length_m)
        .add("flown_length_m", m.flown_length_m)
        .add("rmse_m", m.rmse_m)
        .add("max_error_m", m.max_error_m)
        .add("min_clearance_m", m.min_clearance_m)
        .add("max_speed_mps", m.max_speed_mps)
        .add("radius_m", vl.radius);
    per_vehicle.push_back(j);
  }
  const bool ok = drive && plan.conflicts_message.empty() && log.end_reason == "goal" && reached &&
                  collisions == 0;
  summary.status = ok ? 0 : 1;
  if (!plan.success)
    summary.message = plan.message;
  else if (!quadrotors.ready)
    summary.message = quadrotors.failure;
  else if (log.end_reason == "gave_up")
    summary.message = "the navigator gave up" +
                      (driver && !driver->message().empty() ? ": " + driver->message() : "");
  else if (log.end_reason == "diverged" || log.end_reason == "unstable" ||
           log.end_reason == "saturated")
    summary.message = flightFailureMessage(log.end_reason);
  else if (!reached)
    summary.message = "goal not reached within sim.max_time";
  else if (collisions > 0)
    summary.message = "collision";
  if (!plan.conflicts_message.empty())
    summary.message =
        plan.conflicts_message + (summary.message.empty() ? "" : "; " + summary.message);

  // 5. Files.
  JsonObject metrics;
  metrics.add("reached_goal", reached && drive)
      .add("collisions", collisions)
      .add("planner", name.empty() ? std::string("waypoints") : name)
      .add("planning_time_ms", plan.time_ms)
      .add("planned_length_m", planned)
      .add("flown_length_m", flown)
      .add("flight_time_s", makespan_s)
      .add("rmse_m", samples ? std::sqrt(sum_sq / static_cast<double>(samples)) : 0.0)
      .add("max_error_m", max_error)
      .add("min_clearance_m", clearance)
      .add("sim_speed_x", summary.sim_speed_x)
      .add("error_reference", "timed_plan")
      .add("robots", static_cast<int>(robot_ids.size()))
      .add("robot_contacts", team.robot_contacts)
      .add("obstacle_contacts", team.obstacle_contacts)
      .add("moving_obstacle_contacts", team.moving_obstacle_contacts)
      .add("moving_obstacles", static_cast<int>(scenario.moving_obstacles.size()))
      .add("min_robot_distance_m", team.min_robot_distance_m)
      .add("min_moving_obstacle_distance_m", team.min_moving_obstacle_distance_m)
      .add("planned_makespan_s", planned_makespan)
      .add("executed_makespan_s", makespan_s)
      .add("sum_of_arrival_times_s", sum_arrivals)
      .add("cruise_speed_mps", speed)
      .add("inflation_m", plan.inflation);
  if (!quadrotor_ids.empty())  // the quadrotors over the robots
    metrics.add("uavs", static_cast<int>(quadrotor_ids.size()))
        .add("robot_uav_contacts", team.robot_uav_contacts)
        .add("uav_contacts", team.uav_contacts)
        .add("uav_planner", air.planner_name.empty() ? std::string("waypoints") : air.planner_name)
        .add("uav_trajectory_mode", air.trajectory_mode)
        .add("uav_controller", air.controller_name)
        .add("uav_rmse_m",
             uav_samples ? std::sqrt(uav_sum_sq / static_cast<double>(uav_samples)) : 0.0)
        .add("uav_max_error_m", uav_max_error)
        .add("longest_saturation_s", uav_saturation)
        .add("fault", log.end_reason == "diverged" || log.end_reason == "unstable" ||
                              log.end_reason == "saturated"
                          ? log.end_reason
                          : std::string("none"));
  if (quadrotor_ids.size() > 1) {
    std::vector<SeparationEllipsoid> ellipsoids;
    for (std::size_t v : quadrotor_ids)
      ellipsoids.push_back(
          {world.vehicles()[v].params.separation_radius, world.vehicles()[v].params.separation_height});
    const UavSeparationMetrics u = uavSeparationMetrics(log, quadrotor_ids, ellipsoids);
    metrics.add("min_uav_separation_m", u.min_uav_separation)
        .add("downwash_violations", u.downwash_violations);
  }
  metrics.add("seed", static_cast<long>(scenario.sim.seed))
      .add("sim_time_s", log.sim_time)
      .add("wall_time_s", log.wall_time)
      .add("end_reason", log.end_reason)
      .add("mujoco_warnings", log.mujoco_warnings)
      .add("status", summary.status)
      .add("message", summary.message)
      .add("planner_counters", plan.counters)
      .add("planner_params", plan.params);
  metrics.addArray("vehicles", per_vehicle);

  // Interrupted while rendering: no index.html, no metrics.json, nothing that looks finished.
  if (!writeRunFiles(world, scenario, log, request, drive, metrics, summary))
    return interruptedRun();
  summary.metrics_json = std::move(metrics);
  summary.log = std::move(log);
  return summary;
}

}  // namespace cosim
