// The extension behind `import cosim` (python/cosim/__init__.py re-exports it). The API is
// The Python API (docs/python.md): cosim.run, cosim.plan, cosim.Simulation, cosim.InputError.
#include "python/bindings.h"
#include "python/overrides.h"
#include "python/unknown_vehicle_error.h"
#include "sim/mujoco_messages.h"

PYBIND11_MODULE(_cosim, m) {
  m.doc() =
      "cosim: plan, fly and evaluate scenarios of the cosim co-simulator from Python "
      "(see docs/python.md).";
  // MuJoCo's warnings to stderr as the program prints them, not to MUJOCO_LOG.TXT in the
  // caller's folder.
  cosim::installMujocoMessageHandlers();
  m.attr("DEFAULT_SCENARIO") = cosim::python::defaultScenarioPath();
  m.attr("__version__") = std::string(COSIM_VERSION);
  cosim::python::bindInputError(m);
  cosim::python::bindUnknownVehicleError(m);
  cosim::python::bindRun(m);
  cosim::python::bindPlan(m);
  cosim::python::bindSimulation(m);
}
