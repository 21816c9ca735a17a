#pragma once
// Builds the scenario's flight controller by name, with gains from the scenario's
// controller.gains (every gain optional, misspelt ones an error).
#include <memory>

#include "control/flight_controller.h"
#include "control/quadrotor_params.h"
#include "planning/param_set.h"

namespace cosim {

std::unique_ptr<FlightController> makeFlightController(const std::string& name, ParamSet& gains,
                                                       const QuadrotorParams& params);

}  // namespace cosim
