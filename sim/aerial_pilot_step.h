#pragma once
// One quadrotor's share of the simulation loop (sim/simulation_loop.h; a ground robot's is
// sim/ground_pilot_step.h): at each control step: estimate the state from what the sensors
// delivered (sim/state_estimator.h), ask the reference for the set-point, run the controller,
// turn its rotor thrusts into rotor-speed commands with the flight software's thrust
// coefficient, log a sample, and book arrival, saturation and divergence (judged on the true
// state).
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "control/flight_controller.h"
#include "control/reference_source.h"
#include "sim/quadrotor_plant.h"
#include "sim/run_log.h"
#include "sim/state_estimator.h"
#include "sim/world_model.h"

namespace cosim {

// One vehicle's brain: where its set-point comes from and what turns it into rotor thrusts.
struct VehiclePilot {
  FlightController* controller = nullptr;
  ReferenceSource* reference = nullptr;
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> planned_path;  // for the log
  // s: when a given reference ends (VehicleLog::reference_end); negative: none.
  double reference_end = -1.0;
  // What the flight software believes of the airframe (sim/model_error.h); nullptr: the truth.
  const QuadrotorParams* believed_airframe = nullptr;
};

// When a quadrotor has arrived, has failed, or is lost.
struct AerialStepRules {
  // The run's goal tolerance; diverged beyond ten world diagonals from the world's centre.
  AerialStepRules(const SimSettings& settings, const World& world, double hold_after_arrival,
                  double max_saturated_time);

  double goal_tolerance = 0.2;      // m: arrived within this distance of the goal
  double hold_after_arrival = 1.0;  // s of hovering at the goal before it counts as done
  // A mixer saturated this long without a break cannot follow its reference.
  double max_saturated_time = 2.0;  // s
  // Diverged: a non-finite position, or farther than `far` from `centre`.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double far = 1e9;  // m
};

// How the quadrotors of a run sense themselves: the scenario's sensors and estimator, and the
// seed their noise streams derive from.
struct AerialSensing {
  SensorSettings sensors;
  EstimatorSettings estimator;
  std::uint64_t seed = 1;
};

class AerialPilotStep {
 public:
  AerialPilotStep(const VehicleHandles& vehicle, VehiclePilot& pilot, const AerialStepRules& rules,
                  const AerialSensing& sensing, std::size_t vehicle_index);

  // The vehicle's log entry (name, size, thrust limit, goal, planned path, room for
  // `initial_samples`, growing to at most `most_samples`, sim/log_growth.h); resets the
  // controller and starts the estimator at the state in d.
  VehicleLog begin(const mjData* d, std::size_t initial_samples, std::size_t most_samples);

  struct Outcome {
    bool done = false;       // arrived and held the goal for hold_after_arrival
    bool saturated = false;  // saturated for longer than max_saturated_time
    bool diverged = false;
  };
  // One control step at d->time: commands the plant's rotors and, if `record`, writes a sample
  // into `log`. Arrival and saturation are booked at every step, recorded or not.
  Outcome step(const mjData* d, QuadrotorPlant& plant, double control_dt, VehicleLog& log,
               bool record);

 private:
  const VehicleHandles* vehicle_;
  VehiclePilot* pilot_;
  AerialStepRules rules_;
  const QuadrotorParams* airframe_;  // believed
  StateEstimator estimator_;
  double saturated_since_ = -1.0;  // since when the mixer has been saturated (negative: it is not)
  std::size_t most_samples_ = 0;   // the most samples the run can log (sim/log_growth.h)
};

}  // namespace cosim
