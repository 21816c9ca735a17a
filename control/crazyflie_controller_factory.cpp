#include "control/crazyflie_controller_factory.h"

#include "control/controller_registry.h"

namespace cosim {

std::unique_ptr<FlightController> makeCrazyflieController(const std::string& name, ParamSet& gains,
                                                          const QuadrotorParams& params,
                                                          const CrazyflieThrustPath& thrust_path) {
  const ControllerEntry* entry = ControllerRegistry::instance().find(name);
  if (!entry || !entry->crazyflie_thrust_path) return nullptr;
  return entry->make(params, gains, ControllerOptions{false, thrust_path});
}

}  // namespace cosim
