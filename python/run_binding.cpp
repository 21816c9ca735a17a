// cosim.run: `cosim run` as a function. The pipeline is run/run_pipeline.h's executeRun, as the
// program calls it; without `out` it writes nothing and the result carries the metrics and the
// log in memory.
#include <pybind11/stl.h>

#include <filesystem>
#include <iostream>
#include <optional>

#include "core/output_dir_lock.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "core/stop_request.h"
#include "python/bindings.h"
#include "python/interrupt_guard.h"
#include "python/overrides.h"
#include "python/python_values.h"
#include "python/unknown_vehicle_error.h"
#include "run/metrics_json.h"
#include "run/run_files.h"
#include "run/run_pipeline.h"
#include "run/scenario_checks.h"
#include "sim/run_log_io.h"

namespace py = pybind11;

namespace cosim::python {

namespace {

struct RunResult {
  int status = 0;
  std::string message;
  py::object metrics;
  RunLog log;
  std::optional<std::string> out;

  // The vehicles whose rows `vehicle` asks for: all (None), one by name or by index.
  std::vector<std::size_t> vehiclesFor(const py::object& vehicle) const {
    std::vector<std::string> names;
    for (const VehicleLog& v : log.vehicles) names.push_back(v.name);
    if (!vehicle.is_none()) return {vehicleIndex(vehicle, names)};
    std::vector<std::size_t> all(names.size());
    for (std::size_t v = 0; v < all.size(); ++v) all[v] = v;
    return all;
  }

  py::dict timeseries(const py::object& vehicle) const {
    std::vector<std::pair<std::string, std::vector<double>>> columns;
    py::list names;
    for (std::size_t v : vehiclesFor(vehicle)) {
      auto part = timeseriesColumns(log, v);
      if (columns.empty()) {
        columns = std::move(part);
      } else {
        for (std::size_t c = 0; c < columns.size(); ++c)
          columns[c].second.insert(columns[c].second.end(), part[c].second.begin(),
                                   part[c].second.end());
      }
      for (std::size_t i = 0; i < log.vehicles[v].samples.size(); ++i)
        names.append(log.vehicles[v].name);
    }
    if (columns.empty()) {  // the names still, for a run that never flew
      RunLog unflown;
      unflown.vehicles.emplace_back();
      columns = timeseriesColumns(unflown, 0);
    }
    py::dict table;
    for (const auto& [name, values] : columns) table[py::str(name)] = vectorArray(values);
    table["vehicle"] = py::module_::import("numpy").attr("array")(names, py::arg("dtype") = "str");
    return table;
  }
};

RunResult run(const py::object& scenario, const py::object& overrides, const py::object& out,
              bool video) {
  const std::string path = scenarioPath(scenario);
  const std::vector<std::string> sets = overrideAssignments(overrides);
  std::optional<std::string> out_dir;
  if (!out.is_none()) out_dir = pathArgument(out, "out");

  InterruptGuard guard;
  RunRequest request;
  RunRecord summary;
  std::optional<JsonObject> metrics;  // metrics.json's object, from the record
  {
    py::gil_scoped_release release;
    // As `cosim run` does (cli/cmd_run.cpp): the folder is touched only once the scenario passed
    // its checks (run/run_files.h RunFolderSession).
    if (out_dir) checkOutputDir(*out_dir);
    const Scenario s = loadCheckedScenario(path, sets, PlannerUse::Run);
    std::optional<RunFolderSession> folder;
    if (out_dir) request.out_dir = folder.emplace(*out_dir, "out").dir();
    request.video = video;
    request.interrupt = &stopRequestFlag();
    // Warnings as the program prints them; the rest of its progress lines stay unsaid.
    request.observer = [](const RunEvent& e) {
      if (e.kind == RunEventKind::Warning) std::cerr << "cosim: warning: " << e.text << "\n";
    };
    summary = executeRun(s, request);
    if (summary.outcome != RunOutcome::Interrupted) metrics = runMetricsJson(s, summary);
    if (folder) folder->finish(summary.outcome == RunOutcome::Interrupted);
  }
  guard.finish();  // Ctrl-C: KeyboardInterrupt from here
  RunResult r;
  r.status = summary.exitStatus();
  r.message = summary.message;
  if (metrics) r.metrics = jsonValue(metrics->json());
  r.log = std::move(summary.log);
  if (out_dir) r.out = request.out_dir.string();
  return r;
}

}  // namespace

void bindRun(py::module_& m) {
  py::class_<RunResult>(m, "RunResult", "What cosim.run returns.")
      .def_readonly("status", &RunResult::status,
                    "0: every vehicle reached its goal without a collision; 1: the task failed "
                    "(no path, goal missed, collision), as `cosim run`'s exit status")
      .def_readonly("message", &RunResult::message, "why the task failed ('' on success)")
      .def_readonly("metrics", &RunResult::metrics,
                    "dict: what metrics.json holds (None if a SIGINT handler other than "
                    "Python's default let an interrupted run return)")
      .def_readonly("out", &RunResult::out, "the folder the run's files went to, or None")
      .def("timeseries", &RunResult::timeseries, py::arg("vehicle") = py::none(),
           "The flight log as timeseries.csv holds it: dict of column name -> NumPy array (the "
           "'vehicle' column: names). vehicle=None: every vehicle's rows in the file's order; a "
           "name or an index: that vehicle's rows.")
      .def("__repr__", [](const RunResult& r) {
        return "RunResult(status=" + std::to_string(r.status) +
               ", message=" + py::repr(py::str(r.message)).cast<std::string>() + ")";
      });
  m.def("run", &run, py::arg("scenario") = py::none(), py::arg("overrides") = py::none(),
        py::arg("out") = py::none(), py::arg("video") = false,
        R"(Plan, fly and evaluate a scenario, as `cosim run` does.

scenario: path of a scenario YAML file (None: the bundled default, cosim.DEFAULT_SCENARIO).
overrides: dict of scenario keys to values, e.g. {"planner.name": "astar", "sim.max_time": 20,
    "vehicles[0].goal": [30, 20, 3]}, as `--set key=value` (values become YAML text).
out: None writes nothing and renders nothing; a folder gets `cosim run --out`'s files
    (metrics.json, timeseries.csv, path.csv, final.png, index.html, and video.mp4 if video).
video: render video.mp4 into `out`.

Returns a RunResult (status, message, metrics, timeseries()). Raises cosim.InputError for bad
input, KeyboardInterrupt on Ctrl-C (planning, flight and rendering stop within moments).)");
}

}  // namespace cosim::python
