#pragma once
// The simulation loop for ground robots (URDF bases, sim/urdf_vehicle.h): each robot's
// controller at the control rate follows its timed path, the command becomes drive-servo
// set-points (x/y/yaw velocities of a holonomic base, wheel speeds of a differential drive),
// moving obstacles (mocap bodies) are placed every physics step, mj_step advances, and contacts
// are booked (the floor under a ground robot is not a collision). Logs into a RunLog.
// Quadrotors in the same world fly in the same loop, at the same control rate, each through its
// sim/aerial_pilot_step.h (hover start, reference, flight controller, arrival, saturation); they
// are logged at the robots' instants, so that sample k of every vehicle is at the same time.
#include <atomic>
#include <functional>
#include <vector>

#include "control/ground_controller.h"
#include "control/ground_timed_path.h"
#include "sim/aerial_pilot_step.h"
#include "sim/run_log.h"
#include "sim/world_model.h"

namespace cosim {

struct GroundPilot {
  GroundController* controller = nullptr;
  GroundTimedPath* path = nullptr;  // may be extended during the run (before_control)
  double yaw = 0.0;                 // heading a holonomic base holds, rad
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> planned_path;  // for the log
};

struct GroundSimOptions {
  SimSettings settings;
  double hold_after_arrival = 0.5;         // s at the goal before the run ends
  double aerial_hold_after_arrival = 1.0;  // s a quadrotor hovers at its goal (as in flight)
  double max_saturated_time = 2.0;  // s; a quadrotor saturated longer ends the run "saturated"
  double log_rate = 50.0;           // Hz at most (ground robots move slowly; keeps logs small)
  const std::atomic<bool>* interrupt = nullptr;
  // Called at each control step before the controllers, with the robots' measured states; a
  // navigator extends the pilots' paths here. Returning false ends the run with end_reason
  // "gave_up".
  std::function<bool(double t, const std::vector<PlanarState>& states)> before_control;
  // Centre (x, y) of moving obstacle i at time t; default: the scenario's path and speed.
  std::function<Eigen::Vector2d(std::size_t i, double t)> obstacle_position;
};

// The measured planar state of a ground robot.
PlanarState readPlanarState(const mjData* d, const VehicleHandles& v);

// Runs until every vehicle has reached its goal and held it, max_time, an interrupt, divergence
// (a NaN state, a quadrotor far outside the world), "unstable" (MuJoCo found bad numbers),
// "saturated" (a quadrotor's mixer), or before_control giving up. `robots` are the world's ground
// robots in order, `quadrotors` its other vehicles in order (the log keeps the world's order).
RunLog simulateGround(const WorldModel& world, const Scenario& scenario,
                      std::vector<GroundPilot>& robots, std::vector<VehiclePilot>& quadrotors,
                      const GroundSimOptions& options);
// A world of ground robots only.
RunLog simulateGround(const WorldModel& world, const Scenario& scenario,
                      std::vector<GroundPilot>& pilots, const GroundSimOptions& options);

}  // namespace cosim
