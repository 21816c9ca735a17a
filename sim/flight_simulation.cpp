#include "sim/flight_simulation.h"

namespace cosim {

SimulationOptions flightSimulationOptions(const FlightOptions& options) {
  SimulationOptions o;
  o.settings = options.settings;
  o.aerial_hold_after_arrival = options.hold_after_arrival;
  o.max_saturated_time = options.max_saturated_time;
  o.log_rate = 0.0;  // every control step: a flight's metrics and plots want the full rate
  o.interrupt = options.interrupt;
  o.second_thread = options.second_thread;
  o.profile = options.profile;
  return o;
}

RunLog simulateFlight(const WorldModel& world, const Scenario& scenario,
                      std::vector<VehiclePilot>& pilots, const FlightOptions& options) {
  std::vector<GroundPilot> no_robots;
  SimulationLoop loop(world, scenario, no_robots, pilots, flightSimulationOptions(options));
  while (loop.stepControl()) {
  }
  return loop.finish();
}

}  // namespace cosim
