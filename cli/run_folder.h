#pragma once
// Reading back a folder written by `cosim run` (or `cosim mapf --execute`), for the commands that
// work on a logged run without simulating again (render, export-mcap).
#include <filesystem>

#include "sim/run_log.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim::cli {

// dir/scenario.yaml, its relative paths resolved where the original scenario file was (run.json),
// each vehicle's reference read from the copy the run kept in `dir` (runReferenceCopyName).
// Throws InputError naming the file (dir/scenario.yaml for its own defects) when one is missing
// or malformed.
Scenario readRunScenario(const std::filesystem::path& dir);

// dir/timeseries.csv, path.csv and, if the scenario has moving obstacles and the file exists,
// moving_obstacles.csv; bounded by what the scenario's run could have logged.
RunLog readRunLog(const std::filesystem::path& dir, const Scenario& scenario);

// What the files do not hold, from the scenario and its composed world: each vehicle's goal,
// bounding radius and rotor limit.
void completeRunLog(RunLog& log, const Scenario& scenario, const WorldModel& world);

}  // namespace cosim::cli
