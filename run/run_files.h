#pragma once
// The files of a run, written in an order that never lets an unfinished run look finished: first
// any metrics.json and index.html of an earlier run in the folder go, then the log files
// (scenario.yaml, run.json, path.csv, timeseries.csv), the pictures and videos rendered from the
// log, index.html, and metrics.json last: its presence means the run's files are complete.
#include "run/run_pipeline.h"
#include "sim/world_model.h"

namespace cosim {

// What `cosim run` writes into its folder that says "a run happened" (everything but the copy of
// the scenario, which may be the very file being run): removed before the run starts.
extern const std::vector<std::string> kRunResultNames;

// `render`: whether there is anything to draw (false when planning failed). Returns false, with
// no index.html and no metrics.json written, if the interrupt flag stopped the rendering. Writes
// and renders nothing, returning true, when request.out_dir is empty.
bool writeRunFiles(const WorldModel& world, const Scenario& scenario, const RunLog& log,
                   const RunRequest& request, bool render, const JsonObject& metrics,
                   const RunSummary& summary);

}  // namespace cosim
