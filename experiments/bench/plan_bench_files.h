#pragma once
// The files of `cosim plan-bench`, written into its output folder once every run is made (each
// complete or not at all): runs.csv, summary.csv, summary.md, plan-bench.log (OMPL's benchmark
// log format) and plan_bench.png/.svg. The summary also goes to stdout.
#include <chrono>
#include <filesystem>
#include <vector>

#include "experiments/bench/plan_bench_runs.h"
#include "planning/sampling/collision_world.h"

namespace cosim {

void writePlanBenchFiles(const std::filesystem::path& dir, const PlanBenchProblem& problem,
                         const std::vector<PlanBenchRun>& runs,
                         std::chrono::system_clock::time_point started, double total_s,
                         const CollisionWorld& world);

}  // namespace cosim
