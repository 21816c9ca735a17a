#pragma once
// What a MAPF benchmark runs (mapf_benchmark.h): a MovingAI map, scenario files, planners and
// agent counts, with the limits and parameters of each run.
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "planning/grid/occupancy_grid.h"

namespace cosim {

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

}  // namespace cosim
