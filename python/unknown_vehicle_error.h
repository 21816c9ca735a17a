#pragma once
// cosim.UnknownVehicleError: a vehicle name (or index) the run does not have. Both a KeyError (a
// name looked up like a dict key) and a ValueError (a bad argument), so either except clause
// catches it; str(e) is the plain message, naming the vehicles there are.
#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace cosim::python {

class UnknownVehicle : public std::runtime_error {
 public:
  // `asked`: the name or index as the caller gave it (its repr); `known`: the run's vehicles.
  UnknownVehicle(const std::string& asked, const std::vector<std::string>& known);
};

// The index of `vehicle` (a name, or an index into `names`) in `names`; throws UnknownVehicle.
std::size_t vehicleIndex(const pybind11::handle& vehicle, const std::vector<std::string>& names);

void bindUnknownVehicleError(pybind11::module_& m);

}  // namespace cosim::python
