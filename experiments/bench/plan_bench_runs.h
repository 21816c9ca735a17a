#pragma once
// The rows `cosim plan-bench` collects, one per planner run, and what is computed from them:
// per-planner summaries (median and quartiles) and the CSV and Markdown tables.
#include <map>
#include <string>
#include <vector>

namespace cosim {

struct PlanBenchRun {
  std::string planner;
  bool ompl = false;  // one of OMPL's planners
  int seed = 1;
  bool solved = false;    // an exact path from start to goal
  int status = 0;         // OMPL's PlannerStatus numbering (plan-bench.log's "status" enum)
  double time_ms = 0.0;   // wall-clock time of the planner's solve, all segments
  double length_m = 0.0;  // Euclidean length of the returned path (solved runs)
  int waypoints = 0;
  bool path_clear = false;     // every segment clear of the inflated obstacles (independent check)
  double graph_states = -1.0;  // nodes of the tree or roadmap; < 0 when the planner has none
  std::string message;
  std::map<std::string, std::string> params;  // the planner's parameters in force
};

// Where the planners were compared, for the reports' headers.
struct PlanBenchProblem {
  std::string scenario;          // file name
  std::string start, goal;       // "(x, y, z)"
  int segments = 1;              // start -> waypoints -> goal
  double straight_line_m = 0.0;  // through the waypoints
  double inflation_m = 0.0;
  std::size_t obstacles = 0;
  int runs = 0;
  double time_limit_s = 0.0;
};

// The p-quantile (0..1) with linear interpolation between order statistics (Hyndman & Fan
// 1996, definition 7: R's and numpy's default); 0 for no values.
double quantile(std::vector<double> values, double p);

struct PlannerSummary {
  std::string planner;
  bool ompl = false;
  int runs = 0, solved = 0;
  std::vector<double> times_ms;   // every run
  std::vector<double> lengths_m;  // solved runs
};

// One summary per planner, in the order the planners first appear in `runs`.
std::vector<PlannerSummary> summarizePlanBench(const std::vector<PlanBenchRun>& runs);

std::string planBenchRunsCsv(const std::vector<PlanBenchRun>& runs);
std::string planBenchSummaryCsv(const std::vector<PlannerSummary>& summaries);
std::string planBenchSummaryMarkdown(const PlanBenchProblem& problem,
                                     const std::vector<PlannerSummary>& summaries);

}  // namespace cosim
