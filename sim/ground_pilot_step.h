#pragma once
// One ground robot's share of the simulation loop (sim/simulation_loop.h), the counterpart of a
// quadrotor's sim/aerial_pilot_step.h: at each control step: sample the robot's timed path, run
// its controller on the measured planar state, turn the body-frame command into drive-servo
// set-points (x/y/yaw velocities of a holonomic base, wheel speeds of a differential drive), log
// a sample, and book arrival and divergence. A robot's controller reads its exact state.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "control/ground_controller.h"
#include "control/ground_timed_path.h"
#include "sim/physics_stepper.h"
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

// The measured planar state of a ground robot.
PlanarState readPlanarState(const mjData* d, const VehicleHandles& v);

class GroundPilotStep {
 public:
  // `vehicle_index`: the robot's place in the world (its drive servos in the PhysicsStepper).
  // Arrived within `goal_tolerance` (horizontally) of the goal on the path's final point; done
  // after holding it `hold_after_arrival` s.
  GroundPilotStep(const VehicleHandles& vehicle, std::size_t vehicle_index, GroundPilot& pilot,
                  double goal_tolerance, double hold_after_arrival);

  // The robot's log entry (name, radius, goal, planned path); resets the controller.
  VehicleLog begin();

  struct Outcome {
    bool done = false;  // arrived and held the goal for hold_after_arrival
    bool diverged = false;
  };
  // One control step at d->time from the robot's state `s` (read at this step): commands the
  // drive servos and, if `record`, writes a sample into `log`.
  Outcome step(const mjData* d, const PlanarState& s, PhysicsStepper& physics, double control_dt,
               VehicleLog& log, bool record);

 private:
  void recordSample(const mjData* d, const PlanarState& s, const PlanarReference& ref,
                    const Eigen::Vector3d& pos, const GroundCommand& cmd,
                    const PhysicsStepper& physics, VehicleLog& log) const;

  const VehicleHandles* vehicle_;
  std::size_t index_;
  GroundPilot* pilot_;
  double goal_tolerance_;
  double hold_after_arrival_;
};

}  // namespace cosim
