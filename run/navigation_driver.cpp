#include "run/navigation_driver.h"

#include <chrono>
#include <cmath>

#include "core/input_error.h"
#include "planning/navigation/d_star_lite.h"
#include "planning/navigation/robot_navigation_ant.h"
#include "run/robot_plans.h"
#include "sim/moving_obstacle_motion.h"

namespace cosim {

std::unique_ptr<Navigator> makeNavigator(const std::string& name, ParamSet& p) {
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

NavigationWorld navigationWorld(const Scenario& s, const WorldModel& world, std::size_t robot_id,
                                double resolution, double speed, double margin,
                                double& inflation) {
  const double robot = world.vehicles()[robot_id].params.radius;
  inflation = robot + margin;
  OccupancyGrid grid = robotGrid(s, resolution, inflation);
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

NavigationDriver::NavigationDriver(std::unique_ptr<Navigator> navigator, NavigationWorld world,
                                   const std::string& file, const VehicleSpec& v, double tau,
                                   GroundTimedPath& path)
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
  path_.append(0.0, planarPoint(v.start));
  path_.append(kRobotSettleTime, planarPoint(v.start));
  executed_.push_back(floorPoint(planarPoint(v.start)));
}

// The smoothed reference looks `smoothing` seconds ahead, so the next step is decided that
// early, for the robot at its commanded cell at the time it is due there (its measured
// deviation from the plan is in the metrics).
bool NavigationDriver::update(double t) {
  if (done_ || t + path_.smoothing() + 1e-9 < path_.endTime()) return true;
  const OccupancyGrid& g = world_.grid();
  const Cell at = commanded_;
  t = path_.endTime();
  if (at == goal_cell_) {
    path_.append(t + tau_, planarPoint(goal_));
    executed_.push_back(floorPoint(planarPoint(goal_)));
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
  path_.append(t + tau_ * (diagonal ? std::sqrt(2.0) : 1.0), planarPoint(g.cellCenter(d.next)));
  if (!wait) executed_.push_back(floorPoint(planarPoint(g.cellCenter(d.next))));
  commanded_ = d.next;
  return true;
}

double NavigationDriver::navigationTime(double t) const {
  return std::max(0.0, t - kRobotSettleTime) / tau_;
}

Eigen::Vector2d NavigationDriver::obstacle(std::size_t i, double t) const {
  return planarPoint(world_.obstacleCentre(i, navigationTime(t)));
}

std::map<std::string, double> NavigationDriver::counters() const {
  return {{"decisions", decisions_},
          {"waits", waits_},
          {"replans", replans_},
          {"mean_plan_ms", decisions_ ? plan_ms_ / decisions_ : 0.0}};
}

}  // namespace cosim
