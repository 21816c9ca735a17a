#pragma once
// Where a controller's set-point comes from at each control step: a time-parametrised
// trajectory, or waypoints switched by proximity (seed 003's method).
#include "control/flight_controller.h"

namespace cosim {

class ReferenceSource {
 public:
  virtual ~ReferenceSource() = default;
  // The reference at time t; may depend on the measured state (waypoint switching does).
  virtual FlatReference reference(double t, const VehicleState& state) = 0;
  // True once the last set-point is active (the vehicle is on its way to the goal).
  virtual bool atFinalSetpoint() const = 0;
};

}  // namespace cosim
