#pragma once
// Reading back a folder written by `cosim run` (or `cosim mapf --execute`), for the commands that
// work on a logged run without simulating again (render, export-mcap, compare-real): the one
// reader of a run's record (run/record/run_record.h) from its folder.
#include <filesystem>

#include "run/record/run_record.h"
#include "sim/scenario.h"

namespace cosim::cli {

// dir/scenario.yaml, its relative paths resolved where the original scenario file was (run.json),
// each vehicle's reference read from the copy the run kept in `dir` (runReferenceCopyName).
// Throws InputError naming the file (dir/scenario.yaml for its own defects) when one is missing
// or malformed.
Scenario readRunScenario(const std::filesystem::path& dir);

// The record of the run of `scenario` (readRunScenario's, with any changes a command made to its
// render section) in `dir`: its setup resolved from the scenario as the run resolved it, its log
// from timeseries.csv, path.csv and, if the scenario has moving obstacles and the file exists,
// moving_obstacles.csv (bounded by what the scenario's run could have logged, completed from the
// scenario and its composed world: each vehicle's goal, bounding radius and rotor limit), its
// world, and each vehicle's tracking errors as the run's evaluation measures them
// (run/run_evaluation.h trackVehicles). The log read back holds no arrivals, so the flight
// metrics, plans and outcome are not in it: they stay in the folder's metrics.json and path.csv.
// Throws InputError naming the file when one is missing or malformed.
RunRecord readRunRecord(const std::filesystem::path& dir, const Scenario& scenario);

}  // namespace cosim::cli
