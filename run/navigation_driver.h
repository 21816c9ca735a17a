#pragma once
// A navigator (rna, wf_rna, d_star_lite: planning/navigation/) driving one ground robot among
// moving obstacles, deciding one grid step at a time while the simulation runs.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "control/ground_timed_path.h"
#include "core/param_set.h"
#include "planning/navigation/navigation_world.h"
#include "planning/navigation/navigator.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim {

// The navigator `name` with its main parameter (sight) read from `p`; its other parameters keep
// their defaults here.
std::unique_ptr<Navigator> makeNavigator(const std::string& name, ParamSet& p);

// The navigator's world: the static map as a planar grid, the moving obstacles with their path
// points snapped to cell centres (the navigator's obstacles live on the grid; the physical ones
// then follow the very same trajectories), speeds in cells per robot step. `robot` is the
// robot's index in the scenario; `inflation` receives its radius + the planner's `margin`.
// Throws InputError for moving obstacles too large for the grid.
NavigationWorld navigationWorld(const Scenario& s, const WorldModel& world, std::size_t robot,
                                double resolution, double speed, double margin,
                                double& inflation);

// Drives one robot with a navigator: whenever the robot's commanded step is over, it asks the
// navigator for the next cell (from the robot's commanded cell) and extends the timed path by one
// step. Navigation time runs in robot steps: one cell per `tau` seconds (seed 000 §4.2.3).
class NavigationDriver {
 public:
  // Throws InputError if the robot's start or goal lies in a blocked cell.
  NavigationDriver(std::unique_ptr<Navigator> navigator, NavigationWorld world,
                   const std::string& file, const VehicleSpec& v, double tau,
                   GroundTimedPath& path);

  // Called before each control step (GroundSimOptions::before_control): false when the
  // navigator gives up.
  bool update(double t);

  double navigationTime(double t) const;
  // Where moving obstacle i stands at time t, as the navigator sees it.
  Eigen::Vector2d obstacle(std::size_t i, double t) const;
  // The cells the robot was sent through, as points on the floor (its "planned path").
  const std::vector<Eigen::Vector3d>& executed() const { return executed_; }
  std::map<std::string, double> counters() const;
  const std::string& message() const { return message_; }  // why it gave up

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

}  // namespace cosim
