#pragma once
// A benchmark log in OMPL's format, the one ompl::tools::Benchmark::saveResultsToStream writes
// (OMPL 1.5) and ompl_benchmark_statistics.py reads into the SQLite database that Planner Arena
// (plannerarena.org) shows:
//   OMPL version V / Experiment NAME / K experiment properties (NAME TYPE = VALUE) /
//   Running on HOST / Starting at DATE / <<<| setup |>>> / <<<| cpu |>>> / SEED is the random
//   seed / T seconds per run / M MB per run / N runs per planner / D seconds spent to collect
//   the data / 1 enum type / status|...  / P planners, then per planner: its name, C common
//   properties (NAME = VALUE), R properties for each run (NAME TYPE, sorted), N runs (each value
//   followed by "; ", empty when unknown), and a line ".".
#include <map>
#include <string>
#include <vector>

namespace cosim {

struct OmplLogPlanner {
  std::string name;
  std::map<std::string, std::string> common;  // the planner's parameters
  // One map per run: "property TYPE" (TYPE is REAL, INTEGER, BOOLEAN, ENUM or STRING) -> value.
  std::vector<std::map<std::string, std::string>> runs;
};

struct OmplLogExperiment {
  std::string version;  // of the OMPL that ran, e.g. 1.5.2
  std::string name;     // one word: the reader keeps the last word of the line
  std::map<std::string, std::string> properties;  // "name TYPE" -> value
  std::string host;
  std::string start_time;  // ISO 8601, e.g. 2026-12-02T03:04:05
  std::string setup;       // free text, the problem's description
  std::string cpu;
  unsigned seed = 1;
  double time_limit_s = 0.0;
  double memory_limit_mb = 0.0;
  int runs_per_planner = 0;
  double total_s = 0.0;
  std::vector<OmplLogPlanner> planners;
};

// The log's text. `status_names` are OMPL's PlannerStatus words in enum order.
std::string omplBenchmarkLog(const OmplLogExperiment& experiment,
                             const std::vector<std::string>& status_names);

}  // namespace cosim
