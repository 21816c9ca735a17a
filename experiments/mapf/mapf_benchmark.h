#pragma once
// The MAPF benchmark (`cosim mapf MAP SCEN... --agents START:STOP:STEP --planner A,B,...`):
// every planner at every agent count on the first N agents of each scenario file, as the MAPF
// benchmark's tables are made (Stern et al., SoCS 2019). Writes DIR/benchmark.csv (one row per
// planner, scenario and count), DIR/success_rate.csv and the figure DIR/success_rate.png/.svg
// (success rate against agents, one line per planner), and DIR/benchmark.md (a summary with the
// published LaCAM* figures beside ours). It prints nothing: progress goes to a callback.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>

#include "experiments/mapf/mapf_benchmark_report.h"
#include "experiments/mapf/mapf_benchmark_setup.h"

namespace cosim {

// Called after each run that was made (not for skipped ones): runs done so far (skipped ones
// included), the total, and the run's row.
using MapfBenchmarkProgress =
    std::function<void(std::size_t done, std::size_t total, const MapfBenchmarkRow& row)>;

struct MapfBenchmarkOutcome {
  // A stop request (setup.stop, or the process's, core/stop_request.h) ended the benchmark: no
  // file was written into out_dir.
  bool interrupted = false;
  std::filesystem::path out_dir;
  std::string summary_markdown;  // what benchmark.md holds
};

// Throws InputError for bad input (an unknown or repeated planner, a bad parameter, map,
// scenario file or instance) before anything is run or any folder is made.
MapfBenchmarkOutcome runMapfBenchmark(const MapfBenchmarkSetup& setup,
                                      const MapfBenchmarkProgress& progress = {});

}  // namespace cosim
