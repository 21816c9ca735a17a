#pragma once
// `cosim run --list-controllers`: every flight controller with what it is, its team tracking
// margin, whether it takes drag_compensation and the Crazyflie thrust path, and its gains (name,
// default, valid range, what it does), all from control/controller_registry.h.
#include <string>

namespace cosim::cli {

std::string controllerListText();

}  // namespace cosim::cli
