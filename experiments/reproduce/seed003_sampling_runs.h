#pragma once
// One column of seed003-sampling's tables run many times: which planner with which cap and
// settings, and what the runs give (lengths, times, node counts, the best path). Shared by the
// tables and the checks beside them (goal rule, linear scan, small caps, mode-2 hypotheses).
#include <string>
#include <utility>
#include <vector>

#include "experiments/reproduce/reproduction.h"
#include "experiments/reproduce/seed003_maps.h"
#include "experiments/reproduce/seed003_sampling_tables.h"
#include "planning/path.h"

namespace cosim::reproduce {

// One column of a table: the row name in NAME.json, the registered planner, its choose-parent
// rule and the RRT*FN cap (0: none); seed_index: the thesis's column (-1: not in the thesis).
struct SamplingColumn {
  std::string label, json_name, planner;
  bool thesis_parent;
  int cap;
  int seed_index;
};

// RRT, the thesis's RRT*, Karaman-Frazzoli's RRT*, and the thesis's RRT*FN at the table's caps.
std::vector<SamplingColumn> samplingColumnsOf(const Seed003SamplingTable& t);

struct Samples {
  int runs = 0, successes = 0;
  std::vector<double> lengths, times_ms, nodes, first_path_nodes, removed;
  std::vector<double> goal_costs;  // the goal's cost as the tree holds it (RRT* only)
  Path best;                       // the shortest path over the runs (for the map figures)
};

// How a column is run besides the table's settings: the goal tolerance (< 0: one step, the
// rule of the tables), the nearest-neighbour search, and further planner parameters.
struct RunVariant {
  double goal_tolerance = -1.0;
  bool linear_scan = false;
  std::vector<std::pair<std::string, std::string>> params;
};

Samples runSamplingColumn(const Seed003SamplingTable& t, const Seed003Map& map,
                          const SamplingColumn& col, const Options& options, int runs,
                          const RunVariant& variant = {});

}  // namespace cosim::reproduce
