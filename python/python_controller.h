#pragma once
// A flight controller written in Python: Simulation.set_controller(name, fn) puts one in place
// of a quadrotor's built-in controller (SimulationLoop allows the swap between control steps).
// At each control step it calls fn(state, reference) with what the built-in controller would be
// given, the estimate (a dict as Simulation.state returns) and the reference (position,
// velocity, acceleration, yaw), and takes back the four rotor thrusts in N. The GIL must be held
// while the loop steps (Simulation.step does).
#include <pybind11/pybind11.h>

#include <exception>
#include <functional>
#include <string>

#include "control/flight_controller.h"
#include "control/quadrotor_params.h"

namespace cosim::python {

class PythonController final : public FlightController {
 public:
  // `clock`: the simulated time (for the state's "time"); `airframe`: what the flight software
  // believes, whose thrust range bounds the commands; `vehicle`: its name, for messages.
  PythonController(pybind11::function fn, std::function<double()> clock,
                   const QuadrotorParams& airframe, std::string vehicle);
  // Dropped with the GIL held (the Simulation that owns it is).
  ~PythonController() override = default;

  std::string name() const override { return "python"; }
  void reset() override {}
  // fn's thrusts clamped to the airframe's [min_thrust, max_thrust] (saturated if that changed
  // them). If fn raises, or returns anything but 4 finite numbers (ValueError), the error is kept
  // for takeError and the previous command stands for this control period: the loop itself
  // cannot unwind mid-step.
  ControlOutput update(const VehicleState& state, const FlatReference& ref, double dt) override;

  // What it calls (for the garbage collector's traversal).
  const pybind11::function& function() const { return fn_; }
  // The error of the last update, once (nullptr if none).
  std::exception_ptr takeError();

 private:
  Eigen::Vector4d rotorThrusts(const pybind11::object& returned) const;

  pybind11::function fn_;
  std::function<double()> clock_;
  const QuadrotorParams& airframe_;
  std::string vehicle_;
  ControlOutput last_;  // hover thrust until fn answers
  std::exception_ptr error_;
};

// {"position", "velocity", "acceleration" (arrays, world frame), "yaw" (rad)}.
pybind11::dict referenceDict(const FlatReference& ref);

}  // namespace cosim::python
