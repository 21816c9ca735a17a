#include "control/controller_factory.h"

#include "control/controller_registry.h"
#include "core/input_error.h"

namespace cosim {

std::unique_ptr<FlightController> makeFlightController(const std::string& name, ParamSet& gains,
                                                       const QuadrotorParams& params,
                                                       bool drag_compensation,
                                                       const CrazyflieThrustPath& thrust_path) {
  const ControllerEntry* entry = ControllerRegistry::instance().find(name);
  if (!entry)
    throw InputError(gains.file(), "key controller.name",
                     "unknown controller '" + name + "': " + controllerNameProblem(name));
  auto c = entry->make(params, gains, ControllerOptions{drag_compensation, thrust_path});
  if (drag_compensation && !entry->compensates_drag)
    throw InputError(gains.file(), "key controller.drag_compensation",
                     "drag_compensation applies to the " + dragCompensatingControllers() +
                         " controllers, not to '" + name + "'");
  gains.requireAllUsed("controller '" + name + "'");
  return c;
}

}  // namespace cosim
