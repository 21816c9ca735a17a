#pragma once
// What seed003-sampling concludes from its tables: the per-table ratio summary, the closing
// "Where we agree and where we differ" findings, and the rebuilt maps with the best path of each
// kind of planner.
#include <map>
#include <string>
#include <vector>

#include "experiments/reproduce/agreement_section.h"
#include "experiments/reproduce/reproduction.h"
#include "experiments/reproduce/seed003_maps.h"
#include "experiments/reproduce/seed003_sampling_checks.h"
#include "experiments/reproduce/seed003_sampling_tables.h"
#include "planning/path.h"

namespace cosim::reproduce {

// One table's results, as ratios to the thesis's RRT* (ours) beside the thesis's own.
struct TableFinding {
  const Seed003SamplingTable* table = nullptr;
  double rrt_ratio = 0, kf_ratio = 0;         // mean lengths / the thesis's RRT*
  double star_length = 0;                     // the thesis's RRT* (ours), mean length [m]
  double star_time_ms = 0;                    // and its median time
  double star_time_q1 = 0, star_time_q3 = 0;  // and its interquartile range [ms]
  double star_first = 0;                      // and the nodes generated at its first path (median)
  // Per cap: time / RRT*'s, length / RRT*'s, nodes generated at the first path (median).
  std::vector<double> fn_time_ratio, fn_length_ratio, fn_first;
  std::vector<double> fn_time_q1, fn_time_q3;  // per cap, the interquartile range [ms]
};

// The shortest path of each kind of planner on one map, over all its tables and runs: 0 RRT,
// 1 the thesis's RRT*, 2 Karaman-Frazzoli's RRT*, 3 RRT*FN at any cap.
struct BestPaths {
  Path path[4];
  void offer(std::size_t kind, const Path& p) {
    if (!p.empty() && (path[kind].empty() || p.length() < path[kind].length())) path[kind] = p;
  }
};

// "## Ratios per table": RRT / RRT*, KF / thesis RRT*, RRT*FN time per cap, binding caps.
std::string ratioTable(const std::vector<TableFinding>& findings);

std::vector<Finding> samplingFindings(const std::vector<TableFinding>& findings,
                                      const SamplingChecks& checks);

// Writes seed003-sampling_map<k>.png/.svg per map that has paths; returns the report's section.
std::string samplingMaps(const Options& options, const std::vector<Seed003Map>& maps,
                         const std::map<std::string, BestPaths>& best);

}  // namespace cosim::reproduce
