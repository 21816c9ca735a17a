#include "python/unknown_vehicle_error.h"

namespace py = pybind11;

namespace cosim::python {

namespace {

std::string knownList(const std::vector<std::string>& known) {
  std::string list;
  for (const auto& name : known) list += (list.empty() ? "" : ", ") + name;
  return list;
}

}  // namespace

UnknownVehicle::UnknownVehicle(const std::string& asked, const std::vector<std::string>& known)
    : std::runtime_error("no vehicle " + asked + " in this run (vehicles: " + knownList(known) +
                         ")") {}

std::size_t vehicleIndex(const py::handle& vehicle, const std::vector<std::string>& names) {
  if (py::isinstance<py::str>(vehicle)) {
    const std::string name = vehicle.cast<std::string>();
    for (std::size_t v = 0; v < names.size(); ++v)
      if (names[v] == name) return v;
  } else if (py::isinstance<py::int_>(vehicle) && !py::isinstance<py::bool_>(vehicle)) {
    const py::int_ index = py::reinterpret_borrow<py::int_>(vehicle);
    // Compared as Python ints: an index beyond a C long is as unknown as 7.
    if (index >= py::int_(0) && index < py::int_(names.size())) return index.cast<std::size_t>();
  } else {
    throw py::type_error("name: a vehicle name (str) or index (int) is needed, not " +
                         py::str(py::type::of(vehicle).attr("__name__")).cast<std::string>());
  }
  throw UnknownVehicle(py::repr(vehicle).cast<std::string>(), names);
}

void bindUnknownVehicleError(py::module_& m) {
  // type(name, (KeyError, ValueError), ...), with BaseException's str: KeyError's would quote
  // the message.
  const py::module_ builtins = py::module_::import("builtins");
  py::dict namespace_;
  namespace_["__module__"] = "cosim";
  namespace_["__doc__"] =
      "A vehicle name or index the run does not have (a KeyError and a ValueError).";
  namespace_["__str__"] = builtins.attr("BaseException").attr("__str__");
  // Held for the life of the process (released, never decremented after the interpreter ends).
  static py::handle type =
      builtins
          .attr("type")("UnknownVehicleError",
                        py::make_tuple(builtins.attr("KeyError"), builtins.attr("ValueError")),
                        namespace_)
          .release();
  m.attr("UnknownVehicleError") = type;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const UnknownVehicle& e) {
      PyErr_SetString(type.ptr(), e.what());
    }
  });
}

}  // namespace cosim::python
