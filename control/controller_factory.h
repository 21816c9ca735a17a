#pragma once
// Builds the scenario's flight controller by name (cascade, geometric, indi, dsl_pid,
// crazyflie_lee, crazyflie_mellinger, crazyflie_pid), with gains
// from the scenario's controller.gains (every gain optional, misspelt ones an error).
// drag_compensation (controller.drag_compensation) puts the rotor drag of Faessler et al. 2018
// into the feed-forward of geometric and indi; with another controller it is bad input.
// thrust_path: the crazyflie_* controllers' firmware build (control/crazyflie_thrust_path.h);
// the scenario loader refuses it for other controllers.
#include <memory>

#include "control/crazyflie_thrust_path.h"
#include "control/flight_controller.h"
#include "control/quadrotor_params.h"
#include "core/param_set.h"

namespace cosim {

std::unique_ptr<FlightController> makeFlightController(const std::string& name, ParamSet& gains,
                                                       const QuadrotorParams& params,
                                                       bool drag_compensation = false,
                                                       const CrazyflieThrustPath& thrust_path = {});

}  // namespace cosim
