#pragma once
// `cosim mapf MAP SCEN... --agents START:STOP:STEP --planner A,B,...`: every planner at every
// agent count on the first N agents of each scenario file, as the MAPF benchmark's tables are
// made (Stern et al., SoCS 2019). Writes DIR/benchmark.csv (one row per planner, scenario and
// count), DIR/success_rate.csv and the figure DIR/success_rate.png/.svg (success rate against
// agents, one line per planner), and DIR/benchmark.md (a summary with the published LaCAM*
// figures beside ours). Progress goes to stderr.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "planning/grid/occupancy_grid.h"

namespace cosim::cli {

// "N" or "START:STOP:STEP" (START, START + STEP, ... up to STOP). Throws InputError (place
// --agents) for anything else, counts below 1, STOP below START or more than 10000 counts.
std::vector<int> parseAgentCounts(const std::string& text);

struct MapfBenchmarkSetup {
  std::string map;
  std::vector<std::string> scens;
  std::vector<std::string> planners;
  std::vector<int> counts;
  std::vector<Cell> extra_blocked;  // --block
  int connectivity = 4;
  double time_limit_s = 60.0;
  std::uint64_t seed = 1;
  // "key=value" planner parameters; "PLANNER.key=value" for one planner only.
  std::vector<std::string> sets;
  // false: as the benchmark is usually run, a planner that fails on a scenario at N agents is
  // not run there at larger counts (recorded as "skipped", not solved).
  bool keep_going = false;
  std::string out;  // --out; empty: a new folder under out/ (created after the input checks)
  const std::atomic<bool>* stop = nullptr;
};

// Runs the benchmark; returns the exit status (0 when it ran to the end, 1 if interrupted).
// Throws InputError for bad input before anything is run.
int runMapfBenchmark(const MapfBenchmarkSetup& setup);

}  // namespace cosim::cli
