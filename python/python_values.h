#pragma once
// The library's values as Python's: JSON values as dicts (metrics.json's exact content), points as
// (N, 3) NumPy arrays, vectors and quaternions as 1-D arrays, a vehicle state as a dict.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "control/flight_controller.h"

namespace cosim::python {

// A JSON value as json.loads would give it from its text, built from the value itself (no text
// is written or parsed): objects as dicts in their order, integers as int, other numbers as
// float, null as None.
pybind11::object jsonValue(const nlohmann::ordered_json& value);

pybind11::array_t<double> vectorArray(const std::vector<double>& values);
pybind11::array_t<double> vectorArray(const Eigen::VectorXd& values);
// One row per point: shape (N, 3), also for N = 0.
pybind11::array_t<double> pointsArray(const std::vector<Eigen::Vector3d>& points);
// (w, x, y, z), as MuJoCo and timeseries.csv order them.
pybind11::array_t<double> quaternionArray(const Eigen::Quaterniond& q);

// {"time", "position", "velocity", "quaternion" (w, x, y, z), "angular_velocity" (body frame)}.
pybind11::dict stateDict(double time, const VehicleState& state);

}  // namespace cosim::python
