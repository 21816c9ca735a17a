#include "control/controller_registry.h"

#include "control/cascade_controller.h"
#include "control/crazyflie_lee_controller.h"
#include "control/crazyflie_mellinger_controller.h"
#include "control/crazyflie_pid_controller.h"
#include "control/dsl_pid_controller.h"
#include "control/geometric_controller.h"
#include "control/indi_controller.h"
#include "core/name_suggestion.h"

namespace cosim {

// Each controller registers itself from its own file: its header declares
// `void register<Name>Controller(ControllerRegistry&)`; include it above and call it below. The
// order of the calls is the order of `cosim run --list-controllers` and of the messages.
const ControllerRegistry& ControllerRegistry::instance() {
  static const ControllerRegistry registry = [] {
    ControllerRegistry r;
    registerCascadeController(r);
    registerGeometricController(r);
    registerIndiController(r);
    registerDslPidController(r);
    registerCrazyflieLeeController(r);
    registerCrazyflieMellingerController(r);
    registerCrazyfliePidController(r);
    return r;
  }();
  return registry;
}

const ControllerEntry* ControllerRegistry::find(const std::string& name) const {
  for (const ControllerEntry& e : entries_)
    if (e.name == name) return &e;
  return nullptr;
}

namespace {

// "'a', 'b' or 'c'" (with `conjunction` "or"), "'a' and 'b'" (with "and").
std::string quotedList(const std::vector<std::string>& names, const std::string& conjunction) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += i + 1 == names.size() ? " " + conjunction + " " : ", ";
    text += "'" + names[i] + "'";
  }
  return text;
}

}  // namespace

std::string controllerNameProblem(const std::string& name) {
  if (ControllerRegistry::instance().find(name)) return "";
  std::vector<std::string> names;
  for (const ControllerEntry& e : ControllerRegistry::instance().entries()) names.push_back(e.name);
  const std::string hint = didYouMean(name, names);
  return "must be " + quotedList(names, "or") + (hint.empty() ? "" : " (" + hint + ")");
}

bool compensatesDrag(const std::string& name) {
  const ControllerEntry* e = ControllerRegistry::instance().find(name);
  return e && e->compensates_drag;
}

std::string dragCompensatingControllers() {
  std::vector<std::string> names;
  for (const ControllerEntry& e : ControllerRegistry::instance().entries())
    if (e.compensates_drag) names.push_back(e.name);
  return quotedList(names, "and");
}

bool takesCrazyflieThrustPath(const std::string& name) {
  const ControllerEntry* e = ControllerRegistry::instance().find(name);
  return e && e->crazyflie_thrust_path;
}

}  // namespace cosim
