// cosim mapf MAP.map SCEN.scen --agents N --planner NAME: multi-agent path finding on a MovingAI
// map with the first N agents of a scenario (seed 004). Writes DIR/mapf.json and DIR/paths.csv;
// every plan is checked by the independent SolutionValidator. Exit 0: a conflict-free solution;
// 1: planning failed (no solution, time or step limit) or interrupted; 2: bad input. With a count
// range, a planner list or several scenario files it is a benchmark (experiments/mapf/
// mapf_benchmark.h); one instance is mapf_single.h.
#include <iostream>

#include "cli/command.h"
#include "cli/interrupt_flag.h"
#include "cli/mapf_options.h"
#include "cli/mapf_single.h"
#include "cli/option_checks.h"
#include "core/input_error.h"
#include "experiments/mapf/mapf_benchmark.h"

namespace cosim::cli {

namespace {

// Every planner at every count on every scenario file; progress on stderr, the summary on stdout.
int runBenchmark(const MapfArgs& a, const std::vector<int>& counts,
                 const std::vector<std::string>& planners) {
  if (a.execute)
    throw InputError("command line", "--execute",
                     "drives one plan: give one planner, one scenario and one agent count");
  MapfBenchmarkSetup setup;
  setup.map = a.map;
  setup.scens = a.scens;
  setup.planners = planners;
  setup.counts = counts;
  for (const std::string& b : a.blocks) setup.extra_blocked.push_back(parseBlockCell(b));
  setup.connectivity = a.connectivity;
  setup.time_limit_s = a.time_limit;
  setup.seed = a.seed;
  setup.sets = a.plannerSets();
  setup.keep_going = a.keep_going;
  setup.out = a.out;
  setup.stop = &installInterruptFlag();
  const MapfBenchmarkOutcome outcome =
      runMapfBenchmark(setup, [](std::size_t done, std::size_t total, const MapfBenchmarkRow& r) {
        std::cerr << "cosim: [" << done << "/" << total << "] " << r.planner << ", " << r.agents
                  << " agents, " << fileStem(r.scen) << ": "
                  << (r.success ? "solved, SOC " + std::to_string(r.sum_of_costs)
                                : std::string(mapfRunStatusName(r.status)))
                  << ", " << fixedDigits(r.time_ms, 1) << " ms"
                  << (r.anytime ? " (first solution " + fixedDigits(r.first_solution_ms, 1) + " ms)"
                                : "")
                  << ", tables " << fixedDigits(r.table_mb, 1) << " MB, peak "
                  << fixedDigits(r.peak_rss_mb, 0) << " MB"
                  << (r.message.empty() ? "" : " (" + r.message + ")") << std::endl;
      });
  if (outcome.interrupted) {
    std::cerr << "cosim: interrupted; " << outcome.out_dir.string()
              << " holds no finished benchmark\n";
    return 1;
  }
  std::cout << outcome.summary_markdown << "\nwritten: " << outcome.out_dir.string()
            << "/benchmark.csv, success_rate.csv, success_rate.png, success_rate.svg, "
               "benchmark.md\n";
  return 0;
}

}  // namespace

void addMapfCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand(
      "mapf",
      "Multi-agent path finding on a MovingAI map: the first N agents of SCEN.scen, planned\n"
      "together without collisions (a cell holds one robot; no swaps; 8-connected: diagonal only\n"
      "past free side cells, no crossing diagonals). Cost of an agent = its arrival time; every\n"
      "move, diagonal too, and every wait takes one step. Planners: independent_astar, lra_star,\n"
      "ca_star, hca_star, whca_star, cbs, potential_field, lacam, pibt. Writes DIR/mapf.json,\n"
      "DIR/paths.csv (agent,t,x,y). A benchmark (--agents START:STOP:STEP, several planners\n"
      "A,B,... or several scenario files) runs every planner at every count and writes\n"
      "DIR/benchmark.csv, DIR/success_rate.csv + .png/.svg and DIR/benchmark.md.\n"
      "With --execute, ground robots then drive the plan in MuJoCo (one robot per\n"
      "agent on cells of --cell metres; the map's blocked cells stand as boxes) and "
      "DIR/execution/\n"
      "holds that run's files (scenario.yaml, metrics.json with robot_contacts, arrival times and\n"
      "plan-vs-executed deviation, final.png). Exit 1 if planning (or the execution) fails, 2 on\n"
      "bad input.");
  auto a = std::make_shared<MapfArgs>();
  cmd->add_option("map", a->map, "MovingAI .map file")->required();
  cmd->add_option("scen", a->scens,
                  "MovingAI .scen file(s); the first N lines of one are the agents (several: a "
                  "benchmark over the family)")
      ->required();
  cmd->add_option("--agents", a->agents,
                  "number of agents N, or a benchmark range START:STOP:STEP (e.g. 10:1000:10)")
      ->required()
      ->check(agentCountOrRange());
  cmd->add_option("--planner", a->planner,
                  "multi-robot planner name, or a comma-separated list for a benchmark "
                  "(e.g. lacam,pibt,whca_star,cbs)")
      ->required();
  cmd->add_flag("--keep-going", a->keep_going,
                "benchmark: run a planner at larger counts even after it failed on a scenario");
  cmd->add_option("--window", a->window, "WHCA* window (time steps); same as --set window=W")
      ->check(wholeNumberIn(1, 1000000));
  cmd->add_option("--out", a->out, "output folder (default: a new folder under out/)");
  cmd->add_option("--set", a->sets,
                  "planner parameter, e.g. --set priorities=fixed (repeatable); in a benchmark "
                  "PLANNER.key=value sets it for that planner only (--set lacam.anytime=false)");
  cmd->add_option("--connectivity", a->connectivity, "4 (default, standard MAPF) or 8")
      ->check(CLI::IsMember({4, 8}));
  cmd->add_option("--time-limit", a->time_limit, "seconds per planner run (default 60)")
      ->check(numberIn(0.001, 3600.0));
  cmd->add_option("--seed", a->seed, "random seed (LRA* noise)")->check(seedNumber());
  cmd->add_option("--block", a->blocks, "extra obstacle cell X,Y (column,row; repeatable)");
  cmd->add_flag("--execute", a->execute,
                "drive the plan with ground robots in MuJoCo; files in DIR/execution/");
  cmd->add_option("--robot", a->robot,
                  "--execute: robot model, omni_base (default), diff_drive or a URDF file");
  cmd->add_option("--cell", a->cell,
                  "--execute: cell size in metres (default 0.5 when 4-connected, 0.7 when "
                  "8-connected: room for omni_base)")
      ->check(numberIn(0.05, 100.0));
  cmd->add_option("--max-time", a->max_time,
                  "--execute: simulated seconds before giving up (default 300)")
      ->check(numberIn(1.0, 86400.0));
  cmd->add_flag("--video", a->video, "--execute: also render DIR/execution/video.mp4");
  cmd->add_option("--video-speed", a->video_speed,
                  "--execute --video: time-lapse, simulated seconds per second of video "
                  "(default 4: robots at half a metre per second)")
      ->check(numberIn(0.01, 1000.0));
  cmd->callback([a, &ctx] {
    const std::vector<int> counts = parseAgentCounts(a->agents);
    const std::vector<std::string> planners = splitPlannerList(a->planner);
    ctx.status = counts.size() > 1 || planners.size() > 1 || a->scens.size() > 1
                     ? runBenchmark(*a, counts, planners)
                     : runSingleMapf(*a, counts.front());
  });
}

}  // namespace cosim::cli
