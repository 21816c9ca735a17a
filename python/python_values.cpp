#include "python/python_values.h"

namespace py = pybind11;

namespace cosim::python {

py::object jsonValue(const nlohmann::ordered_json& value) {
  switch (value.type()) {
    case nlohmann::ordered_json::value_t::object: {
      py::dict d;
      for (const auto& [key, item] : value.items()) d[py::str(key)] = jsonValue(item);
      return d;
    }
    case nlohmann::ordered_json::value_t::array: {
      py::list l;
      for (const auto& item : value) l.append(jsonValue(item));
      return l;
    }
    case nlohmann::ordered_json::value_t::string:
      return py::str(value.get_ref<const std::string&>());
    case nlohmann::ordered_json::value_t::boolean:
      return py::bool_(value.get<bool>());
    case nlohmann::ordered_json::value_t::number_integer:
      return py::int_(value.get<std::int64_t>());
    case nlohmann::ordered_json::value_t::number_unsigned:
      return py::int_(value.get<std::uint64_t>());
    case nlohmann::ordered_json::value_t::number_float:
      return py::float_(value.get<double>());
    default:
      return py::none();
  }
}

py::array_t<double> vectorArray(const std::vector<double>& values) {
  py::array_t<double> a(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

py::array_t<double> vectorArray(const Eigen::VectorXd& values) {
  return vectorArray(std::vector<double>(values.data(), values.data() + values.size()));
}

py::array_t<double> pointsArray(const std::vector<Eigen::Vector3d>& points) {
  py::array_t<double> a({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  auto rows = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) rows(static_cast<py::ssize_t>(i), k) = points[i][k];
  return a;
}

py::array_t<double> quaternionArray(const Eigen::Quaterniond& q) {
  return vectorArray(std::vector<double>{q.w(), q.x(), q.y(), q.z()});
}

py::dict stateDict(double time, const VehicleState& state) {
  py::dict d;
  d["time"] = time;
  d["position"] = vectorArray(Eigen::VectorXd(state.position));
  d["velocity"] = vectorArray(Eigen::VectorXd(state.velocity));
  d["quaternion"] = quaternionArray(state.attitude);
  d["angular_velocity"] = vectorArray(Eigen::VectorXd(state.angular_velocity));
  return d;
}

}  // namespace cosim::python
