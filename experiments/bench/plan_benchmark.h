#pragma once
// `cosim plan-bench SCENARIO --planners LIST --runs N --time T`: our single-vehicle planners and
// OMPL's (ompl_rrt, ompl_rrt_connect, ompl_rrt_star, ompl_informed_rrt_star, ompl_prm) on the
// scenario's own collision world (its obstacles grown by the first vehicle's radius plus
// planner.margin, its start, waypoints and goal, its bounds less the clearance above the floor),
// each planner N times with seeds 1..N and T seconds per run. Writes DIR/runs.csv (one row per
// run), DIR/summary.csv and DIR/summary.md (success rate, time and path length with median and
// quartiles), DIR/plan-bench.log in OMPL's benchmark log format (ompl_benchmark_statistics.py
// turns it into the database Planner Arena reads) and the figure DIR/plan_bench.png/.svg.
#include <string>
#include <vector>

namespace cosim {

struct PlanBenchSetup {
  std::string scenario;
  std::vector<std::string> sets;  // --set key=value overrides of the scenario
  std::vector<std::string> planners;
  int runs = 10;
  double time_limit_s = 1.0;
  std::string out;  // --out; empty: a new folder under out/ (created when the runs are done)
};

// The planner names plan-bench accepts: every planner of the registry (`cosim plan --list`)
// and OMPL's five.
std::vector<std::string> planBenchPlannerNames();

// Runs the benchmark; returns the exit status (0 when every run was made, 1 if interrupted).
// Throws InputError for bad input (unknown planner, with the closest name; N < 1; T <= 0; bad
// scenario or parameters) before anything runs or is written.
int runPlanBenchmark(const PlanBenchSetup& setup);

}  // namespace cosim
