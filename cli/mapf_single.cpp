#include "cli/mapf_single.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <limits>

#include "cli/interrupt_flag.h"
#include "cli/mapf_execution.h"
#include "cli/run_console.h"
#include "cli/set_options.h"
#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/json_writer.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "core/peak_memory.h"
#include "planning/mapf/mapf_memory_estimate.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/mapf/movingai_instance.h"
#include "planning/mapf/solution_validator.h"
#include "run/robot_plans.h"
#include "run/run_pipeline.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim::cli {

namespace {

std::string pathsCsv(const std::vector<MapfPath>& paths) {
  std::string csv = "agent,t,x,y\n";
  for (std::size_t a = 0; a < paths.size(); ++a)
    for (std::size_t t = 0; t < paths[a].size(); ++t)
      csv += std::to_string(a) + "," + std::to_string(t) + "," + std::to_string(paths[a][t].x) +
             "," + std::to_string(paths[a][t].y) + "\n";
  return csv;
}

MapfInstance readInstance(const MapfArgs& a, int agents) {
  const std::string& scen = a.scens.front();
  MapfInstance inst = readMovingAIMapfInstance(a.map, scen, agents, a.connectivity);
  for (const std::string& b : a.blocks) {
    const Cell c = parseBlockCell(b);
    if (!inst.grid.inside(c)) throw InputError("command line", "--block " + b, "off the map");
    inst.grid.setBlocked(c, true);
  }
  checkMapfInstance(inst, a.blocks.empty() ? scen : "--block");
  checkMapfTableMemory(inst, a.planner, scen);
  return inst;
}

// The execution's scenario, checked before planning: a robot model that does not load or does
// not fit the cells is bad input found at once, not after a plan has been written.
Scenario executionScenario(const MapfArgs& a, const MapfInstance& inst) {
  MapfExecutionSetup setup;
  setup.map_path = std::filesystem::absolute(a.map).string();
  for (const std::string& b : a.blocks) setup.extra_blocked.push_back(parseBlockCell(b));
  setup.starts = inst.starts;
  setup.goals = inst.goals;
  setup.planner = a.planner;
  setup.planner_sets = a.plannerSets();
  setup.connectivity = inst.connectivity;
  setup.time_limit_s = a.time_limit;
  setup.seed = a.seed;
  // A URDF file named relative to here must still be found from DIR/execution/scenario.yaml.
  const bool urdf = a.robot.size() > 5 && a.robot.substr(a.robot.size() - 5) == ".urdf";
  setup.robot = urdf ? std::filesystem::absolute(a.robot).string() : a.robot;
  setup.cell = a.cell > 0 ? a.cell : (inst.connectivity == 8 ? 0.7 : 0.5);
  setup.max_time_s = a.max_time;
  setup.video_speed = a.video_speed;
  Scenario execution = parseScenario(mapfExecutionScenarioYaml(setup), "--execute");
  double radius = 0.0;
  const WorldModel robots = WorldModel::build(execution);
  for (const VehicleHandles& v : robots.vehicles()) radius = std::max(radius, v.params.radius);
  checkRobotsFitGridMap(execution, radius, inst.connectivity);
  return execution;
}

// The planner's outcome as the validator judges it.
struct CheckedPlan {
  bool success = false;
  PlannerStatus status = PlannerStatus::Unknown;
  std::string message;
  MapfValidation check;
};

CheckedPlan checkPlan(const MapfInstance& inst, const MapfResult& result) {
  CheckedPlan c;
  // Nothing returned (e.g. an unreachable goal) has nothing to check.
  c.check = result.paths.empty() ? MapfValidation{} : validateMapfSolution(inst, result.paths);
  // The planner's word is not enough: a solution is what the validator accepts.
  c.success = result.success && c.check.valid();
  c.status = result.success && !c.check.valid() ? PlannerStatus::InvalidSolution : result.status;
  c.message = result.message;
  if (result.success && !c.check.valid())
    c.message = "planner returned an invalid solution: " +
                (c.check.problems.empty() ? std::to_string(c.check.conflicts.size()) + " conflicts"
                                          : c.check.problems.front());
  return c;
}

std::string mapfJson(const MapfArgs& a, const MapfInstance& inst, const ParamSet& params,
                     const MapfResult& result, const CheckedPlan& plan) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  JsonObject json;
  json.add("success", plan.success)
      .add("status", toString(plan.status))
      .add("agents", inst.agentCount())
      .add("sum_of_costs", plan.success ? static_cast<double>(sumOfCosts(result.paths)) : nan)
      .add("makespan", plan.success ? static_cast<double>(makespan(result.paths)) : nan)
      .add("time_ms", result.time_ms)
      .add("peak_rss_mb", static_cast<double>(peakResidentBytes()) / (1 << 20))
      .add("conflicts", static_cast<int>(plan.check.conflicts.size()))
      .add("invalid_steps", static_cast<int>(plan.check.problems.size()))
      .add("planner", a.planner)
      .add("params", params.effective())
      .add("connectivity", inst.connectivity)
      .add("map", a.map)
      .add("scen", a.scens.front())
      .add("cost_convention",
           "sum of arrival times; every move (diagonal too) and every wait costs one step")
      .add("counters", result.counters)
      .add("message", plan.message);
  return json.str() + "\n";
}

// Ground robots drive the written plan in MuJoCo; the run's files go to DIR/execution/.
int executePlan(const MapfArgs& a, Scenario execution, const MapfResult& plan,
                const std::filesystem::path& dir, const std::atomic<bool>& interrupt) {
  const std::filesystem::path exec_dir = dir / "execution";
  std::filesystem::create_directories(exec_dir);
  execution.file = (exec_dir / "scenario.yaml").string();  // where the run writes it
  RunRequest request;
  request.out_dir = exec_dir;
  request.video = a.video;
  request.interrupt = &interrupt;
  request.given_team_plan = &plan;  // the plan just written, not a second search
  RunConsole console(true);
  request.observer = console.observer();
  const RunRecord run = executeRun(execution, request);
  console.finish();
  if (run.outcome == RunOutcome::Interrupted) {
    std::cerr << "cosim: interrupted; " << exec_dir.string() << " holds no finished run\n";
    return 1;
  }
  int contacts = 0, arrived = 0;
  double deviation = 0.0;
  for (const FlightMetrics& m : run.metrics.vehicles) {
    contacts += m.collisions;
    arrived += m.reached_goal ? 1 : 0;
    deviation = std::max(deviation, m.max_error_m);
  }
  std::cout << "executed in physics: " << arrived << "/" << run.metrics.vehicles.size()
            << " robots arrived, " << contacts << " contacts, max deviation from the plan "
            << deviation << " m\nwritten: " << exec_dir.string() << "/ (metrics.json)\n";
  if (run.outcome == RunOutcome::TaskFailed)
    std::cerr << "cosim: execution: " << run.message << "\n";
  return run.exitStatus();
}

}  // namespace

int runSingleMapf(const MapfArgs& a, int agents) {
  // Interruptible from here on; the folder is checked before any work and, once the inputs
  // passed their checks, loses an earlier result before planning (a failing rerun must not leave
  // an old execution/metrics.json in place). Only files cosim can prove it wrote go: anything
  // else under those names refuses the command, and bad input touches nothing.
  const std::atomic<bool>& interrupt = installInterruptFlag();
  checkOutputDir(a.out);
  ParamSet params("command line");
  applySetOptions(a.sets, params);
  if (a.window > 0) params.set("window", std::to_string(a.window), "--window");
  auto planner = makeMapfPlanner(a.planner, params);
  const MapfInstance inst = readInstance(a, agents);
  const Scenario execution = a.execute ? executionScenario(a, inst) : Scenario{};
  removeStaleResults(a.out, {"mapf.json", "paths.csv", "execution"});

  MapfQuery query;
  query.instance = &inst;
  query.time_limit_s = a.time_limit;
  query.seed = a.seed;
  const MapfResult result = planner->solve(query, StopToken::untimed(&interrupt));
  // A planner ended by the stop request says so; a request that came after it returned is an
  // interrupt all the same: either way its outcome is no result.
  if (result.status == PlannerStatus::Stopped || interrupt.load()) {
    std::cerr << "cosim: interrupted; "
              << (a.out.empty() ? std::string("no folder was written") : a.out + " holds no plan")
              << "\n";
    return 1;
  }
  const CheckedPlan plan = checkPlan(inst, result);
  const std::filesystem::path dir = prepareOutputDir(a.out, "mapf");
  // What the command writes (execution/ included) is recorded in the folder's manifest, last.
  OutputManifestScope manifest(dir, "mapf");
  writeFileAtomically(dir / "paths.csv", pathsCsv(result.paths));
  writeFileAtomically(dir / "mapf.json", mapfJson(a, inst, params, result, plan));
  std::cout << a.planner << ": " << (plan.success ? "solved" : "failed") << ", "
            << inst.agentCount() << " agents";
  if (plan.success)
    std::cout << ", sum of costs " << sumOfCosts(result.paths) << ", makespan "
              << makespan(result.paths);
  std::cout << ", " << result.time_ms << " ms" << (plan.message.empty() ? "" : ": " + plan.message)
            << "\nwritten: " << dir.string() << "/mapf.json, paths.csv\n";
  if (!a.execute) {
    manifest.finish();
    return plan.success ? 0 : 1;
  }
  if (!plan.success) {
    manifest.finish();
    std::cerr << "cosim: no valid plan to execute\n";
    return 1;
  }
  const int status = executePlan(a, execution, result, dir, interrupt);
  manifest.finish(interrupt.load() ? "unfinished" : "complete");
  return status;
}

}  // namespace cosim::cli
