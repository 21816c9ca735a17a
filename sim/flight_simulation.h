#pragma once
// A flight of quadrotors to its end: sim/simulation_loop.h stepped until it stops, with a log
// sample at every control step. Each quadrotor's part of a control step is
// sim/aerial_pilot_step.h.
#include <atomic>
#include <vector>

#include "sim/aerial_pilot_step.h"
#include "sim/run_log.h"
#include "sim/simulation_loop.h"
#include "sim/world_model.h"

namespace cosim {

struct FlightOptions {
  SimSettings settings;
  double hold_after_arrival = 1.0;               // s of hovering at the goal before the run ends
  const std::atomic<bool>* interrupt = nullptr;  // set by SIGINT/SIGTERM handlers
  // A vehicle whose mixer stays saturated this long without a break cannot follow its reference
  // (absurd gains, too heavy, a reference beyond the airframe): the run ends as "saturated".
  double max_saturated_time = 2.0;  // s
  bool second_thread = false;       // SimulationOptions::second_thread
  LoopProfile* profile = nullptr;   // SimulationOptions::profile
};

// The loop's options for a flight: every control step logged, hold_after_arrival for the
// quadrotors.
SimulationOptions flightSimulationOptions(const FlightOptions& options);

// Runs until every vehicle has reached its goal and held it, or max_time, or an interrupt, or a
// fault: end_reason "diverged" (NaN, far outside the world), "unstable" (MuJoCo found bad numbers
// in the state or controls and would reset it) or "saturated" (see max_saturated_time).
RunLog simulateFlight(const WorldModel& world, const Scenario& scenario,
                      std::vector<VehiclePilot>& pilots, const FlightOptions& options);

}  // namespace cosim
