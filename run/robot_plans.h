#pragma once
// The ground robots' plans for a run, each a timed path (control/ground_timed_path.h) at the
// cruise speed: a multi-robot planner's team plan on the planar grid (one grid step per step
// time), a single-agent plan (or the given waypoints) per robot, or a navigator deciding one
// robot's steps while it drives (run/navigation_driver.h).
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "control/ground_timed_path.h"
#include "planning/grid/occupancy_grid.h"
#include "planning/mapf/mapf_problem.h"
#include "run/group_plan.h"
#include "run/record/run_setup.h"
#include "run/scenario_planning.h"
#include "sim/world_model.h"

namespace cosim {

class NavigationDriver;

// Robots settle on their wheels before the plan's clock starts.
constexpr double kRobotSettleTime = 0.2;  // s

inline Eigen::Vector2d planarPoint(const Eigen::Vector3d& p) {
  return p.head<2>();
}
inline Eigen::Vector3d floorPoint(const Eigen::Vector2d& p) {
  return {p.x(), p.y(), 0.0};
}

// The planar grid robots plan on: the world's obstacles grown by `inflation`, at the height of a
// small robot's body.
OccupancyGrid robotGrid(const Scenario& scenario, double resolution, double inflation);

struct RobotPlans {
  RobotPlans();
  RobotPlans(RobotPlans&&) noexcept;
  RobotPlans& operator=(RobotPlans&&) noexcept;
  ~RobotPlans();

  PlanStatus status = PlanStatus::Ready;
  std::string message;  // why not Ready ("no team plan: ...", "the team plan has 3 conflicts")
  double cruise_speed = 0.0;  // m/s, the speed the plans are timed at
  // One per robot when planned (a navigator's grows during the drive), corners rounded to the
  // robots' acceleration limit.
  std::vector<GroundTimedPath> paths;
  std::vector<VehiclePlan> plans;  // one per robot planned: its planner's result
  PlanSummary summary;
  std::unique_ptr<NavigationDriver> navigator;  // with Planning::Navigator
};

// Plans scenario.vehicles[i] for each i in setup.robots with the scenario's top-level planner.
// Throws InputError for bad planner or trajectory parameters, starts or goals the planner's grid
// cannot hold, or robots too large for world.grid_map's cells.
// With `given_team_plan` (Planning::Team only), that plan is timed and driven instead of the
// planner's own.
RobotPlans planRobots(const Scenario& scenario, const RunSetup& setup, const WorldModel& world,
                      const MapfResult* given_team_plan = nullptr);

// Throws InputError (at world.grid_map.cell) unless robots of `robot_radius` plus the planner's
// margin fit the cells of the scenario's grid map for a team plan of `connectivity` (4 or 8).
void checkRobotsFitGridMap(const Scenario& scenario, double robot_radius, int connectivity);

}  // namespace cosim
