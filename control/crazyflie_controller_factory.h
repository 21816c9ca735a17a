#pragma once
// Builds a Crazyflie firmware law (a registry entry on the Crazyflie thrust path:
// control/controller_registry.h) with gains from controller.gains (every gain optional, named
// after the firmware's parameters; misspelt ones are an error at the caller's requireAllUsed).
// Defaults are the firmware's (docs/crazyflie.md).
#include <memory>

#include "control/crazyflie_thrust_path.h"
#include "control/flight_controller.h"
#include "control/quadrotor_params.h"
#include "core/param_set.h"

namespace cosim {

// nullptr if `name` is not a Crazyflie firmware law. `thrust_path`: the build's thrust path
// (controller thrust_map, thrust_map_coefficients, idle_thrust, platform).
std::unique_ptr<FlightController> makeCrazyflieController(
    const std::string& name, ParamSet& gains, const QuadrotorParams& params,
    const CrazyflieThrustPath& thrust_path = CrazyflieThrustPath{});

}  // namespace cosim
