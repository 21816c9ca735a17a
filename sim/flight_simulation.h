#pragma once
// The simulation loop: controllers at their rate, mj_step at the physics rate, a logger at the
// control rate, contact bookkeeping every step. Short on purpose: read it top to bottom.
#include <atomic>
#include <vector>

#include "control/flight_controller.h"
#include "control/reference_source.h"
#include "sim/run_log.h"
#include "sim/world_model.h"

namespace cosim {

// One vehicle's brain: where its set-point comes from and what turns it into rotor thrusts.
struct VehiclePilot {
  FlightController* controller = nullptr;
  ReferenceSource* reference = nullptr;
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> planned_path;  // for the log
};

struct FlightOptions {
  SimSettings settings;
  double hold_after_arrival = 1.0;  // s of hovering at the goal before the run ends
  const std::atomic<bool>* interrupt = nullptr;  // set by SIGINT/SIGTERM handlers
  // A vehicle whose mixer stays saturated this long without a break cannot follow its reference
  // (absurd gains, too heavy, a reference beyond the airframe): the run ends as "saturated".
  double max_saturated_time = 2.0;  // s
};

// The measured state of a vehicle's free body.
VehicleState readVehicleState(const mjModel* m, const mjData* d, const VehicleHandles& v);

// Runs until every vehicle has reached its goal and held it, or max_time, or an interrupt, or a
// fault: end_reason "diverged" (NaN, far outside the world), "unstable" (MuJoCo found bad numbers
// in the state or controls and would reset it) or "saturated" (see max_saturated_time).
RunLog simulateFlight(const WorldModel& world, const Scenario& scenario,
                      std::vector<VehiclePilot>& pilots, const FlightOptions& options);

}  // namespace cosim
