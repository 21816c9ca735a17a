#pragma once
// One run of a multi-robot planner on one instance, judged by the independent SolutionValidator
// (a run counts as solved only if the validator accepts its paths). Shared by the seed-004
// reproductions and the MAPF bench section.
#include <string>
#include <utility>
#include <vector>

#include "planning/mapf/mapf_problem.h"

namespace cosim {

struct MapfTrial {
  bool solved = false;
  long sum_of_costs = 0;  // valid when solved
  int makespan = 0;
  double time_ms = 0.0;
  int conflicts = 0;            // found by the validator in whatever the planner returned
  std::string message;          // the planner's reason for failing (empty when solved)
  std::vector<MapfPath> paths;  // what the planner returned (for the map figures)
};

// Success rate and means over repeated trials of one configuration.
struct MapfTrialSummary {
  int runs = 0, solved = 0;
  double soc_total = 0.0, time_total_ms = 0.0;
  void add(const MapfTrial& t) {
    ++runs;
    time_total_ms += t.time_ms;
    if (t.solved) ++solved, soc_total += static_cast<double>(t.sum_of_costs);
  }
  double successPercent() const { return runs ? 100.0 * solved / runs : 0.0; }
  double meanSumOfCosts() const { return solved ? soc_total / solved : 0.0; }
  double meanTimeMs() const { return runs ? time_total_ms / runs : 0.0; }
};

// v with `digits` decimals; "-" for NaN (nothing to average).
std::string formatFixed(double v, int digits);

MapfTrial runMapfTrial(const std::string& planner,
                       const std::vector<std::pair<std::string, std::string>>& params,
                       const MapfInstance& instance, double time_limit_s, std::uint64_t seed);

}  // namespace cosim
