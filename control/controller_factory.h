#pragma once
// Builds the scenario's flight controller by name (the names of control/controller_registry.h),
// with gains from the scenario's controller.gains (every gain optional, misspelt ones an error
// with a did-you-mean). drag_compensation (controller.drag_compensation) puts the rotor drag of
// Faessler et al. 2018 into the feed-forward of the controllers that compensate drag; with
// another controller it is bad input. thrust_path: the Crazyflie firmware laws' build
// (control/crazyflie_thrust_path.h); the scenario loader refuses it for other controllers.
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
