#include "sim/ground_simulation.h"

namespace cosim {

RunLog simulateGround(const WorldModel& world, const Scenario& scenario,
                      std::vector<GroundPilot>& pilots, const GroundSimOptions& options) {
  std::vector<VehiclePilot> none;
  return simulateGround(world, scenario, pilots, none, options);
}

RunLog simulateGround(const WorldModel& world, const Scenario& scenario,
                      std::vector<GroundPilot>& robots, std::vector<VehiclePilot>& quadrotors,
                      const GroundSimOptions& options) {
  SimulationLoop loop(world, scenario, robots, quadrotors, options);
  while (loop.stepControl()) {
  }
  return loop.finish();
}

}  // namespace cosim
