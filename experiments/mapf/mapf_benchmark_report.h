#pragma once
// The MAPF benchmark's tables, from its rows (one per planner, scenario file and agent count):
// benchmark.csv, success_rate.csv and the summary benchmark.md. Pure text: the runs are made by
// mapf_benchmark.h, which writes these files.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "experiments/mapf/mapf_benchmark_setup.h"

namespace cosim {

// How one planner's run on one instance ended: solved, failed (no solution within its limits), or
// skipped (not run: the planner failed on this scenario file at fewer agents, without
// --keep-going).
enum class MapfRunStatus { Solved, Failed, Skipped };
const char* mapfRunStatusName(MapfRunStatus status);  // "solved", "failed", "skipped"

struct MapfBenchmarkRow {
  std::string scen, planner;
  int agents = 0;
  MapfRunStatus status = MapfRunStatus::Failed;
  bool success = false;
  long sum_of_costs = 0;
  int makespan = 0;
  double time_ms = 0.0;
  bool anytime = false;  // the planner reported a first solution (LaCAM*)
  double first_solution_ms = 0.0;
  long first_cost = 0;
  int conflicts = 0;
  // Memory: the planner's own tables (distance tables as far as searched, LaCAM*'s search) and
  // the process's peak resident set so far (it never falls, so later rows include earlier ones).
  double table_mb = 0.0;
  double peak_rss_mb = 0.0;
  std::string message;
};

// Per planner and agent count: (runs, solved runs); skipped runs count as not solved.
using MapfBenchmarkTally = std::map<std::pair<std::string, int>, std::pair<int, int>>;
MapfBenchmarkTally tallyMapfBenchmark(const std::vector<MapfBenchmarkRow>& rows);

// benchmark.csv: one line per row.
std::string mapfBenchmarkCsv(const std::string& map, const std::vector<MapfBenchmarkRow>& rows);
// success_rate.csv: planner, agents, instances, solved, success_rate_percent.
std::string mapfSuccessRateCsv(const MapfBenchmarkSetup& setup, const MapfBenchmarkTally& tally);
// benchmark.md: the setup, `notes` as a list, a table per planner (against CBS's optimal sum of
// costs), success rates by agent count, the anytime planners' improvement and the published
// LaCAM* figures.
std::string mapfBenchmarkMarkdown(const MapfBenchmarkSetup& setup,
                                  const std::vector<MapfBenchmarkRow>& rows,
                                  const MapfBenchmarkTally& tally,
                                  const std::vector<std::string>& notes);

// "%.*f" of v; a file's name without folder or extension.
std::string fixedDigits(double v, int digits);
std::string fileStem(const std::string& path);

}  // namespace cosim
