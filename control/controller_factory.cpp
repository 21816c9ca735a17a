#include "control/controller_factory.h"

#include <map>
#include <vector>

#include "control/controller_registry.h"
#include "core/input_error.h"
#include "core/owner_list.h"

namespace cosim {

namespace {
// Each gain some registered controller declares -> "controllers a, b" (who takes it), so that a
// gain of another controller is named as that one's, not as a misspelling.
std::map<std::string, std::string> controllersByGain() {
  std::map<std::string, std::vector<std::string>> names;
  for (const ControllerEntry& e : ControllerRegistry::instance().entries())
    for (const GainKey& g : gainKeys(e.gains)) names[g.key].push_back(e.name);
  std::map<std::string, std::string> text;
  for (const auto& [gain, controllers] : names) text[gain] = ownerList("controller", controllers);
  return text;
}
}  // namespace

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
  gains.requireAllUsed("controller '" + name + "'", controllersByGain());
  return c;
}

}  // namespace cosim
