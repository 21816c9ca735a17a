#pragma once
// `cosim run` as a function: plan -> reference -> fly in MuJoCo -> evaluate -> write the run's
// files -> render. Used by the run command and by sweeps.
#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/flight_metrics.h"
#include "core/json_writer.h"
#include "sim/run_log.h"
#include "sim/scenario.h"

namespace cosim {

struct RunRequest {
  // Created beforehand. Empty: no files at all and nothing rendered (the caller, e.g. Python's
  // cosim.run, takes the metrics and the log from the RunSummary).
  std::filesystem::path out_dir;
  bool video = true;
  bool images = true;     // final.png
  bool progress = false;  // progress lines on stderr
  const std::atomic<bool>* interrupt = nullptr;
  // Plan for a point: ignore the vehicle's size and the margin, as seed 003 did (for its
  // reproduction only; flights planned this way clip obstacles).
  bool plan_as_point_mass = false;
};

struct RunSummary {
  int status = 0;       // CONTRACT.md exit status: 0 ok, 1 task failed
  std::string message;  // why the task failed
  std::vector<FlightMetrics> metrics;
  double sim_speed_x = 0.0;
  JsonObject metrics_json;  // exactly what metrics.json holds (also when no files are written)
  RunLog log;               // what timeseries.csv and path.csv are written from
};

// Throws InputError for bad input discovered late (unknown planner, bad gains). Stopped by the
// request's interrupt flag (between stages, in planning, flight and rendering), it returns
// interruptedRun() having written no metrics.json or index.html.
RunSummary executeRun(Scenario& scenario, const RunRequest& request);

// Whether the request's interrupt flag is set; what a run stopped by it returns.
bool stopRequestedFor(const RunRequest& request);
RunSummary interruptedRun();

// A quadrotor's entry in metrics.json's "vehicles" list (without its name and model).
JsonObject flightMetricsJson(const FlightMetrics& m);

// Why a run whose vehicles all planned did not succeed, from the simulation's end_reason.
std::string flightFailureMessage(const std::string& end_reason);

// A quadrotor's longest stretch of continuous mixer saturation in the log, in seconds.
double longestSaturation(const VehicleLog& vehicle);

}  // namespace cosim
