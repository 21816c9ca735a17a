// cosim.plan: `cosim plan` as a function (cli/cmd_plan.cpp): the first vehicle's path in the
// scenario's world, without physics.
#include <pybind11/stl.h>

#include "planning/planner_status.h"
#include "python/bindings.h"
#include "python/interrupt_guard.h"
#include "python/overrides.h"
#include "python/python_values.h"
#include "run/scenario_checks.h"
#include "run/scenario_planning.h"

namespace py = pybind11;

namespace cosim::python {

namespace {

// What Python sees as cosim.PlanResult (named apart from the planners' PlanResult).
struct PythonPlanResult {
  bool success = false;
  std::string status;  // plan.json's: how the search ended (planning/planner_status.h)
  double length_m = 0.0;
  double time_ms = 0.0;
  py::array_t<double> path;
  std::string planner, message;
  double inflation_m = 0.0;
  std::map<std::string, double> counters;
  std::map<std::string, std::string> params;
};

PythonPlanResult plan(const py::object& scenario, const py::object& planner,
                      const py::object& overrides) {
  const std::string path = scenarioPath(scenario);
  const std::vector<std::string> sets = overrideAssignments(overrides);
  if (!planner.is_none() && !py::isinstance<py::str>(planner))
    throw py::type_error("planner: a planner name (str) or None is needed, not " +
                         typeName(planner));
  const std::string planner_name = planner.is_none() ? "" : planner.cast<std::string>();

  InterruptGuard guard;
  VehiclePlan p;
  std::string used_planner;
  {
    py::gil_scoped_release release;
    // An error about the planner argument names it as cosim plan names --planner.
    const Scenario s = loadScenarioForPlan(path, sets, planner_name);
    p = planFirstVehicle(s);
    used_planner = s.motion.planner.name;
  }
  // The planner stopped early: its outcome is no result.
  if (guard.finish()) {
    p = VehiclePlan();
    p.status = PlannerStatus::Stopped;
    p.message = "interrupted";
  }

  PythonPlanResult r;
  r.success = p.success;
  r.status = toString(p.status);
  r.length_m = p.success ? p.path.length() : 0.0;
  r.time_ms = p.time_ms;
  r.path = pointsArray(p.path.waypoints);
  r.planner = used_planner;
  r.message = p.message;
  r.inflation_m = p.inflation;
  r.counters = p.counters;
  r.params = p.params;
  return r;
}

}  // namespace

void bindPlan(py::module_& m) {
  py::class_<PythonPlanResult>(m, "PlanResult", "What cosim.plan returns (plan.json's fields).")
      .def_readonly("success", &PythonPlanResult::success)
      .def_readonly("status", &PythonPlanResult::status,
                    "how the search ended: exact_solution, timeout, no_solution, "
                    "limit_reached, invalid_start, ... (plan.json's status)")
      .def_readonly("length_m", &PythonPlanResult::length_m, "path length, m (0 without a path)")
      .def_readonly("time_ms", &PythonPlanResult::time_ms, "planning time, ms")
      .def_readonly("path", &PythonPlanResult::path, "waypoints, an (N, 3) NumPy array, metres")
      .def_readonly("planner", &PythonPlanResult::planner)
      .def_readonly("message", &PythonPlanResult::message, "why there is no path ('' with one)")
      .def_readonly("inflation_m", &PythonPlanResult::inflation_m,
                    "vehicle radius + margin the planner kept clear of obstacles, m")
      .def_readonly("counters", &PythonPlanResult::counters,
                    "planner counters (expansions, los_checks, iterations, nodes, ...)")
      .def_readonly("params", &PythonPlanResult::params, "the planner's parameters in force")
      .def("__repr__", [](const PythonPlanResult& r) {
        return "PlanResult(success=" + std::string(r.success ? "True" : "False") +
               ", length_m=" + std::to_string(r.length_m) +
               ", time_ms=" + std::to_string(r.time_ms) + ", planner='" + r.planner + "')";
      });
  m.def("plan", &plan, py::arg("scenario") = py::none(), py::arg("planner") = py::none(),
        py::arg("overrides") = py::none(),
        R"(Plan the first vehicle's path in a scenario's world, without physics, as `cosim plan`.

scenario: path of a scenario YAML file (None: the bundled default).
planner: a planner name (overrides planner.name), e.g. "rrt_connect"; None: the scenario's.
overrides: dict of scenario keys to values, as for cosim.run.

Returns a PythonPlanResult (success, length_m, time_ms, path as an (N, 3) array, counters, params).
Raises cosim.InputError for bad input, KeyboardInterrupt on Ctrl-C.)");
}

}  // namespace cosim::python
