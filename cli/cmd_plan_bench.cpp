// cosim plan-bench SCENARIO --planners LIST --runs N --time T [--out DIR]: our planners against
// OMPL's on the scenario's collision world (experiments/bench/plan_benchmark.h).
#include "experiments/bench/plan_benchmark.h"
#include "cli/command.h"
#include "cli/interrupt_flag.h"
#include "cli/option_checks.h"
#include "core/input_error.h"

namespace cosim::cli {

void addPlanBenchCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand(
      "plan-bench",
      "Benchmark planners on a scenario's world: ours (any name of `cosim plan --list`) and\n"
      "OMPL 1.5's (ompl_rrt, ompl_rrt_connect, ompl_rrt_star, ompl_informed_rrt_star,\n"
      "ompl_prm) on the same collision world: the obstacles grown by the first vehicle's radius\n"
      "plus planner.margin, its start, waypoints and goal, the world's bounds. Every planner runs\n"
      "N times (seeds 1..N) with T seconds per run; OMPL's planners check states and motions with\n"
      "our exact tests. The scenario's planner parameters (step, k, ...) apply to ours; OMPL's\n"
      "RRT family takes `step` (default 2 m) as its range. Path length: Euclidean, of the path as\n"
      "returned (OMPL's not simplified). Writes DIR/runs.csv, summary.csv, summary.md,\n"
      "plan-bench.log (OMPL's benchmark log: `ompl_benchmark_statistics.py plan-bench.log` makes\n"
      "the database Planner Arena reads) and plan_bench.png/.svg (time, length, success rate).");
  auto setup = std::make_shared<PlanBenchSetup>();
  cmd->add_option("scenario", setup->scenario, "scenario YAML")->required();
  cmd->add_option("--planners", setup->planners, "planner names, comma-separated")
      ->required()
      ->delimiter(',');
  cmd->add_option("--runs", setup->runs, "runs per planner, seeds 1..N (default 10)")
      ->check(wholeNumberIn(1, 100000));
  cmd->add_option("--time", setup->time_limit_s, "time limit per run, seconds (default 1)")
      ->check(numberIn(1e-6, 3600));
  cmd->add_option("--out", setup->out, "output folder (default: a new folder under out/)");
  cmd->add_option("--set", setup->sets, "override a scenario key, e.g. --set planner.margin=0.2");
  cmd->callback([setup, &ctx] {
    installInterruptFlag();
    ctx.status = runPlanBenchmark(*setup);
  });
}

}  // namespace cosim::cli
