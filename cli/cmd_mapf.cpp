// cosim mapf MAP.map SCEN.scen --agents N --planner NAME: multi-agent path finding on a MovingAI
// map with the first N agents of a scenario (seed 004). Writes DIR/mapf.json and DIR/paths.csv;
// every plan is checked by the independent SolutionValidator. Exit 0: a conflict-free solution;
// 1: planning failed (no solution, time or step limit) or interrupted; 2: bad input. With a count
// range, a planner list or several scenario files it is a benchmark (mapf_benchmark.h).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>

#include "cli/command.h"
#include "run/robot_plans.h"
#include "cli/interrupt_flag.h"
#include "cli/mapf_benchmark.h"
#include "cli/mapf_execution.h"
#include "cli/option_checks.h"
#include "core/atomic_file.h"
#include "cli/run_console.h"
#include "core/output_files.h"
#include "run/run_pipeline.h"
#include "cli/set_options.h"
#include "core/input_error.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/mapf/movingai_instance.h"
#include "planning/mapf/solution_validator.h"
#include "core/json_writer.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim::cli {

namespace {

// "X,Y" (column, row) of a user-defined obstacle cell (seed 004 §5.1: obstacles set by the user).
Cell parseCell(const std::string& text) {
  const auto comma = text.find(',');
  try {
    if (comma != std::string::npos) {
      std::size_t used_x = 0, used_y = 0;
      const int x = std::stoi(text.substr(0, comma), &used_x);
      const int y = std::stoi(text.substr(comma + 1), &used_y);
      if (used_x == comma && used_y == text.size() - comma - 1) return {x, y, 0};
    }
  } catch (const std::exception&) {
  }
  throw InputError("command line", "--block " + text, "expected X,Y (column,row)");
}

// "a,b,c" -> {"a", "b", "c"}; empty names are bad input.
std::vector<std::string> splitPlannerList(const std::string& text) {
  std::vector<std::string> names;
  std::size_t from = 0;
  for (;;) {
    const auto comma = text.find(',', from);
    const std::string name = text.substr(from, comma == std::string::npos ? comma : comma - from);
    if (name.empty())
      throw InputError("command line", "--planner " + text, "empty planner name in the list");
    names.push_back(name);
    if (comma == std::string::npos) return names;
    from = comma + 1;
  }
}

std::string pathsCsv(const std::vector<MapfPath>& paths) {
  std::string csv = "agent,t,x,y\n";
  for (std::size_t a = 0; a < paths.size(); ++a)
    for (std::size_t t = 0; t < paths[a].size(); ++t)
      csv += std::to_string(a) + "," + std::to_string(t) + "," + std::to_string(paths[a][t].x) +
             "," + std::to_string(paths[a][t].y) + "\n";
  return csv;
}

// --agents: a benchmark range START:STOP:STEP is checked by parseAgentCounts; a single count must
// be a whole number within the planners' limit.
CLI::Validator agentCountOrRange() {
  const CLI::Validator count = wholeNumberIn(1, kMaxMapfAgents);
  return CLI::Validator(
      [count](std::string& input) -> std::string {
        if (input.find(':') != std::string::npos) return "";
        std::string copy = input;
        return count(copy);
      },
      "N or START:STOP:STEP");
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
  struct Args {
    std::string map, planner, out, agents;
    std::vector<std::string> scens;
    int window = 0, connectivity = 4;
    bool keep_going = false;
    double time_limit = 60.0;
    bool execute = false, video = false;
    std::string robot = "omni_base";
    double cell = 0.0, max_time = 300.0, video_speed = 4.0;
    std::uint64_t seed = 1;
    std::vector<std::string> sets, blocks;
  };
  auto a = std::make_shared<Args>();
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
  cmd->add_option("--seed", a->seed, "random seed (LRA* noise)");
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
    if (counts.size() > 1 || planners.size() > 1 || a->scens.size() > 1) {
      if (a->execute)
        throw InputError("command line", "--execute",
                         "drives one plan: give one planner, one scenario and one agent count");
      MapfBenchmarkSetup setup;
      setup.map = a->map;
      setup.scens = a->scens;
      setup.planners = planners;
      setup.counts = counts;
      for (const std::string& b : a->blocks) setup.extra_blocked.push_back(parseCell(b));
      setup.connectivity = a->connectivity;
      setup.time_limit_s = a->time_limit;
      setup.seed = a->seed;
      setup.sets = a->sets;
      if (a->window > 0) setup.sets.push_back("window=" + std::to_string(a->window));
      setup.keep_going = a->keep_going;
      setup.out = a->out;
      setup.stop = &installInterruptFlag();
      ctx.status = runMapfBenchmark(setup);
      return;
    }
    const std::string scen = a->scens.front();
    const int agents = counts.front();
    // Interruptible from here on; the folder is checked before any work and loses an earlier
    // result at once (a failing rerun must not leave an old execution/metrics.json in place).
    const std::atomic<bool>& interrupt = installInterruptFlag();
    checkOutputDir(a->out);
    removeStaleResults(a->out, {"mapf.json", "paths.csv", "execution"});
    ParamSet params("command line");
    applySetOptions(a->sets, params);
    if (a->window > 0) params.set("window", std::to_string(a->window), "--window");
    auto planner = makeMapfPlanner(a->planner, params);

    MapfInstance inst = readMovingAIMapfInstance(a->map, scen, agents, a->connectivity);
    for (const std::string& b : a->blocks) {
      const Cell c = parseCell(b);
      if (!inst.grid.inside(c)) throw InputError("command line", "--block " + b, "off the map");
      inst.grid.setBlocked(c, true);
    }
    checkMapfInstance(inst, a->blocks.empty() ? scen : "--block");

    // The execution's scenario, checked before planning: a robot model that does not load or
    // does not fit the cells is bad input found at once, not after a plan has been written.
    Scenario execution;
    if (a->execute) {
      MapfExecutionSetup setup;
      setup.map_path = std::filesystem::absolute(a->map).string();
      for (const std::string& b : a->blocks) setup.extra_blocked.push_back(parseCell(b));
      setup.starts = inst.starts;
      setup.goals = inst.goals;
      setup.planner = a->planner;
      setup.planner_sets = a->sets;
      if (a->window > 0) setup.planner_sets.push_back("window=" + std::to_string(a->window));
      setup.connectivity = inst.connectivity;
      setup.time_limit_s = a->time_limit;
      setup.seed = a->seed;
      // A URDF file named relative to here must still be found from DIR/execution/scenario.yaml.
      const bool urdf = a->robot.size() > 5 && a->robot.substr(a->robot.size() - 5) == ".urdf";
      setup.robot = urdf ? std::filesystem::absolute(a->robot).string() : a->robot;
      setup.cell = a->cell > 0 ? a->cell : (inst.connectivity == 8 ? 0.7 : 0.5);
      setup.max_time_s = a->max_time;
      setup.video_speed = a->video_speed;
      execution = parseScenario(mapfExecutionScenarioYaml(setup), "--execute");
      double radius = 0.0;
      const WorldModel robots = WorldModel::build(execution);
      for (const VehicleHandles& v : robots.vehicles()) radius = std::max(radius, v.params.radius);
      checkRobotsFitGridMap(execution, radius, inst.connectivity);
    }

    MapfQuery query;
    query.instance = &inst;
    query.time_limit_s = a->time_limit;
    query.seed = a->seed;
    query.stop = &interrupt;
    const MapfResult result = planner->solve(query);
    if (interrupt.load()) {  // the planner stopped early: its outcome is no result
      std::cerr << "cosim: interrupted; "
                << (a->out.empty() ? std::string("no folder was written")
                                   : a->out + " holds no plan")
                << "\n";
      ctx.status = 1;
      return;
    }
    // Nothing returned (e.g. an unreachable goal) has nothing to check.
    const MapfValidation check =
        result.paths.empty() ? MapfValidation{} : validateMapfSolution(inst, result.paths);
    // The planner's word is not enough: a solution is what the validator accepts.
    const bool success = result.success && check.valid();
    std::string message = result.message;
    if (result.success && !check.valid())
      message = "planner returned an invalid solution: " +
                (check.problems.empty() ? std::to_string(check.conflicts.size()) + " conflicts"
                                        : check.problems.front());

    const double nan = std::numeric_limits<double>::quiet_NaN();
    JsonObject json;
    json.add("success", success)
        .add("agents", inst.agentCount())
        .add("sum_of_costs", success ? static_cast<double>(sumOfCosts(result.paths)) : nan)
        .add("makespan", success ? static_cast<double>(makespan(result.paths)) : nan)
        .add("time_ms", result.time_ms)
        .add("conflicts", static_cast<int>(check.conflicts.size()))
        .add("invalid_steps", static_cast<int>(check.problems.size()))
        .add("planner", a->planner)
        .add("params", params.effective())
        .add("connectivity", inst.connectivity)
        .add("map", a->map)
        .add("scen", scen)
        .add("cost_convention",
             "sum of arrival times; every move (diagonal too) and every wait costs one step")
        .add("counters", result.counters)
        .add("message", message);

    const std::filesystem::path dir = prepareOutputDir(a->out, "mapf");
    writeFileAtomically(dir / "paths.csv", pathsCsv(result.paths));
    writeFileAtomically(dir / "mapf.json", json.str() + "\n");
    std::cout << a->planner << ": " << (success ? "solved" : "failed") << ", " << inst.agentCount()
              << " agents";
    if (success)
      std::cout << ", sum of costs " << sumOfCosts(result.paths) << ", makespan "
                << makespan(result.paths);
    std::cout << ", " << result.time_ms << " ms" << (message.empty() ? "" : ": " + message)
              << "\nwritten: " << dir.string() << "/mapf.json, paths.csv\n";
    ctx.status = success ? 0 : 1;
    if (!a->execute) return;
    if (!success) {
      std::cerr << "cosim: no valid plan to execute\n";
      return;
    }

    const std::filesystem::path exec_dir = dir / "execution";
    std::filesystem::create_directories(exec_dir);
    execution.file = (exec_dir / "scenario.yaml").string();  // where the run writes it
    RunRequest request;
    request.out_dir = exec_dir;
    request.video = a->video;
    request.interrupt = &interrupt;
    RunConsole console(true);
    request.observer = console.observer();
    const RunSummary run = executeRun(execution, request);
    console.finish();
    if (run.message == "interrupted") {
      std::cerr << "cosim: interrupted; " << exec_dir.string() << " holds no finished run\n";
      ctx.status = 1;
      return;
    }
    int contacts = 0, arrived = 0;
    double deviation = 0.0;
    for (const FlightMetrics& m : run.metrics) {
      contacts += m.collisions;
      arrived += m.reached_goal ? 1 : 0;
      deviation = std::max(deviation, m.max_error_m);
    }
    std::cout << "executed in physics: " << arrived << "/" << run.metrics.size()
              << " robots arrived, " << contacts << " contacts, max deviation from the plan "
              << deviation << " m\nwritten: " << exec_dir.string() << "/ (metrics.json)\n";
    if (run.status != 0) std::cerr << "cosim: execution: " << run.message << "\n";
    ctx.status = run.status;
  });
}

}  // namespace cosim::cli
