#include "python/python_controller.h"

#include <pybind11/numpy.h>

#include "python/python_values.h"

namespace py = pybind11;

namespace cosim::python {

py::dict referenceDict(const FlatReference& ref) {
  py::dict d;
  d["position"] = vectorArray(Eigen::VectorXd(ref.position));
  d["velocity"] = vectorArray(Eigen::VectorXd(ref.velocity));
  d["acceleration"] = vectorArray(Eigen::VectorXd(ref.acceleration));
  d["yaw"] = ref.yaw;
  return d;
}

PythonController::PythonController(py::function fn, std::function<double()> clock,
                                   const QuadrotorParams& airframe, std::string vehicle)
    : fn_(std::move(fn)),
      clock_(std::move(clock)),
      airframe_(airframe),
      vehicle_(std::move(vehicle)) {
  const double hover = airframe_.mass * airframe_.gravity / 4.0;
  last_.rotor_thrusts = Eigen::Vector4d::Constant(hover);
  last_.collective_thrust = 4.0 * hover;
}

Eigen::Vector4d PythonController::rotorThrusts(const py::object& returned) const {
  const std::string who = "the controller of '" + vehicle_ + "'";
  py::array_t<double, py::array::c_style | py::array::forcecast> a;
  try {
    a = py::module_::import("numpy").attr("asarray")(returned, py::arg("dtype") = "float64");
  } catch (const py::error_already_set&) {
    throw py::value_error(who + " returned " + py::repr(returned).cast<std::string>() +
                          ", not 4 rotor thrusts in N");
  }
  if (a.ndim() != 1 || a.shape(0) != 4) {
    std::string shape = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i)
      shape += (i ? ", " : "") + std::to_string(a.shape(i));
    throw py::value_error(who + " returned an array of shape " + shape +
                          (a.ndim() == 1 ? ",)" : ")") +
                          ": it must return 4 rotor thrusts in N, shape (4,)");
  }
  const Eigen::Vector4d u(a.at(0), a.at(1), a.at(2), a.at(3));
  if (!u.allFinite())
    throw py::value_error(who + " returned a thrust that is not a finite number: " +
                          py::repr(returned).cast<std::string>());
  return u;
}

ControlOutput PythonController::update(const VehicleState& state, const FlatReference& ref,
                                       double) {
  try {
    const py::object returned = fn_(stateDict(clock_(), state), referenceDict(ref));
    const Eigen::Vector4d asked = rotorThrusts(returned);
    ControlOutput out;
    out.rotor_thrusts = asked.cwiseMax(airframe_.min_thrust).cwiseMin(airframe_.max_thrust);
    out.saturated = out.rotor_thrusts != asked;
    out.collective_thrust = out.rotor_thrusts.sum();
    last_ = out;
  } catch (...) {
    error_ = std::current_exception();
  }
  return last_;
}

std::exception_ptr PythonController::takeError() {
  return std::exchange(error_, nullptr);
}

}  // namespace cosim::python
