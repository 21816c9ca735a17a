#include "experiments/bench/plan_benchmark.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "core/input_error.h"
#include "core/name_suggestion.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "core/stop_request.h"
#include "experiments/bench/ompl/ompl_planner_runs.h"
#include "experiments/bench/plan_bench_files.h"
#include "planning/planner_registry.h"
#include "run/scenario_planning.h"
#include "sim/world_model.h"

namespace cosim {

namespace {

void checkPlannerNames(const std::vector<std::string>& planners) {
  if (planners.empty()) throw InputError("command line", "--planners", "no planner named");
  const std::vector<std::string> known = planBenchPlannerNames();
  for (const std::string& name : planners) {
    if (std::count(planners.begin(), planners.end(), name) > 1)
      throw InputError("command line", "--planners", "'" + name + "' is named twice");
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    const std::string hint = didYouMean(name, known);
    throw InputError("command line", "--planners " + name,
                     "unknown planner '" + name + "'" + (hint.empty() ? "" : "; " + hint) +
                         " (`cosim plan --list` lists ours; OMPL's are ompl_rrt, "
                         "ompl_rrt_connect, ompl_rrt_star, ompl_informed_rrt_star, ompl_prm)");
  }
}

// The scenario's planner parameters for one of our planners, with the benchmark's time limit.
ParamSet ourParams(const Scenario& s, double time_limit_s) {
  ParamSet p = s.motion.planner.params;
  char limit[32];
  std::snprintf(limit, sizeof limit, "%.17g", time_limit_s);
  p.set("time_limit", limit, "--time");
  return p;
}

// Every segment of `path` clear of the inflated obstacles (the check OMPL's benchmark calls a
// "correct solution").
bool pathClear(const std::vector<Eigen::Vector3d>& path, const CollisionWorld& world) {
  for (std::size_t i = 1; i < path.size(); ++i)
    if (!world.segmentFree(path[i - 1], path[i])) return false;
  return !path.empty();
}

PlanBenchRun runOurs(const std::string& name, Scenario& s, const VehicleSpec& vehicle,
                     double radius, double time_limit_s, int seed, const CollisionWorld& world) {
  s.motion.planner.name = name;
  s.sim.seed = static_cast<std::uint64_t>(seed);
  const VehiclePlan plan = planVehicle(s, vehicle, radius, ourParams(s, time_limit_s));
  PlanBenchRun r;
  r.planner = name;
  r.seed = seed;
  r.solved = plan.success && !plan.path.empty();
  r.time_ms = plan.time_ms;
  r.message = plan.message;
  // OMPL's planners report every failure to find a path as TIMEOUT ("the planner failed to
  // find a solution"); ours are reported the same way, their reason in `message`.
  r.status = r.solved ? omplbench::omplStatusExact() : omplbench::omplStatusTimeout();
  const auto nodes = plan.counters.find("nodes");
  r.graph_states = nodes == plan.counters.end() ? -1.0 : nodes->second;
  if (r.solved) {
    r.length_m = plan.path.length();
    r.waypoints = static_cast<int>(plan.path.size());
    r.path_clear = pathClear(plan.path.waypoints, world);
    r.params = plan.params;
  }
  return r;
}

// OMPL's planner from the start through the vehicle's waypoints to the goal, one segment at a
// time (as planVehicle runs ours), sharing the time limit.
PlanBenchRun runOmpl(const std::string& name, const VehicleSpec& vehicle, double range,
                     double time_limit_s, int seed, const CollisionWorld& world) {
  PlanBenchRun r;
  r.planner = name;
  r.ompl = true;
  r.seed = seed;
  r.solved = true;
  r.graph_states = 0.0;
  std::vector<Eigen::Vector3d> path = {vehicle.start};
  for (const Eigen::Vector3d& target : vehicle.waypoints) {
    omplbench::OmplPlanRequest q;
    q.planner = name;
    q.world = &world;
    q.start = path.back();
    q.goal = target;
    if (vehicle.kind == VehicleKind::GroundRobot) q.goal.z() = q.start.z();
    q.planar = vehicle.kind == VehicleKind::GroundRobot;
    q.time_limit_s = std::max(1e-3, time_limit_s - r.time_ms / 1000.0);
    q.seed = static_cast<std::uint32_t>(seed);
    q.range = range;
    const omplbench::OmplPlanResult out = omplbench::planWithOmpl(q);
    r.time_ms += out.time_ms;
    r.graph_states += out.graph_states;
    r.status = out.status;
    r.params = out.params;
    if (!out.exact || out.path.empty()) {
      r.solved = false;
      r.message = "no exact solution (" + omplbench::omplStatusNames().at(out.status) + ")";
      return r;
    }
    path.insert(path.end(), out.path.begin() + 1, out.path.end());
  }
  Path p;
  p.waypoints = path;
  r.length_m = p.length();
  r.waypoints = static_cast<int>(path.size());
  r.path_clear = pathClear(path, world);
  return r;
}

std::string describe(const Eigen::Vector3d& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%g, %g, %g)", p.x(), p.y(), p.z());
  return buf;
}

PlanBenchProblem describeProblem(const PlanBenchSetup& setup, const Scenario& s,
                                 const VehicleSpec& v, double inflation) {
  PlanBenchProblem p;
  p.scenario = setup.scenario;
  p.start = describe(v.start);
  p.goal = describe(v.goal());
  p.segments = static_cast<int>(v.waypoints.size());
  Eigen::Vector3d from = v.start;
  for (const auto& w : v.waypoints) p.straight_line_m += (w - from).norm(), from = w;
  p.inflation_m = inflation;
  p.obstacles = s.world.obstacles.size();
  p.runs = setup.runs;
  p.time_limit_s = setup.time_limit_s;
  return p;
}

}  // namespace

std::vector<std::string> planBenchPlannerNames() {
  std::vector<std::string> names;
  for (const auto& e : PlannerRegistry::instance().entries()) names.push_back(e.name);
  for (const auto& n : omplbench::omplPlannerNames()) names.push_back(n);
  return names;
}

int runPlanBenchmark(const PlanBenchSetup& setup) {
  // Everything that can be bad input is checked before the first run.
  checkPlannerNames(setup.planners);
  if (setup.runs < 1)
    throw InputError("command line", "--runs",
                     "must be at least 1, got " + std::to_string(setup.runs));
  if (!(setup.time_limit_s > 0.0) || setup.time_limit_s > kMaxPlannerTimeLimit)
    throw InputError("command line", "--time", "must be above 0 and at most 3600 s");
  checkOutputDir(setup.out);
  Scenario s = loadScenario(setup.scenario, setup.sets);
  const WorldModel model = WorldModel::build(s);  // the vehicle's radius comes from its model
  const VehicleSpec& vehicle = s.vehicles.front();
  const double radius = model.vehicles().front().params.radius;
  const double inflation = radius + s.motion.planner.margin;
  for (const std::string& name : setup.planners) {
    if (omplbench::isOmplPlanner(name)) continue;
    ParamSet p = ourParams(s, setup.time_limit_s);
    p.getDouble("time_limit", setup.time_limit_s);  // planVehicle's, not the planner's
    std::vector<std::string> ignored;
    makePlanner(name, p, "--planners " + name, &ignored);  // throws for bad parameters
  }
  // The files an earlier bench wrote are replaced only if cosim can prove it wrote them
  // (core/output_manifest.h): anything else under their names refuses the bench before it runs.
  if (!setup.out.empty())
    for (const auto& p : matchingOutputs(setup.out, {"runs.csv", "summary.csv", "summary.md",
                                                     "plan-bench.log", "plan_bench.*"}))
      requireCosimOutput(p, "--out");
  // OMPL's tree planners take our `step` as their range (maximum edge length).
  ParamSet step_param = s.motion.planner.params;
  const double range = step_param.getDouble("step", 2.0, 1e-3, 1e6);
  // The world our sampling planners build for each solve (SamplingContext), built once here.
  const CollisionWorld world(s.world, inflation, inflation,
                             vehicle.kind == VehicleKind::GroundRobot);

  const auto started = std::chrono::system_clock::now();
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<PlanBenchRun> runs;
  const std::size_t total = setup.planners.size() * static_cast<std::size_t>(setup.runs);
  for (const std::string& name : setup.planners) {
    for (int seed = 1; seed <= setup.runs; ++seed) {
      if (stopRequested()) {
        std::cerr << "cosim: interrupted; no benchmark written\n";
        return 1;
      }
      runs.push_back(omplbench::isOmplPlanner(name)
                         ? runOmpl(name, vehicle, range, setup.time_limit_s, seed, world)
                         : runOurs(name, s, vehicle, radius, setup.time_limit_s, seed, world));
      const PlanBenchRun& r = runs.back();
      char line[160];
      std::snprintf(line, sizeof line, "cosim: [%zu/%zu] %s seed %d: %s, %.1f ms", runs.size(),
                    total, name.c_str(), seed, r.solved ? "solved" : "not solved", r.time_ms);
      std::cerr << line
                << (r.solved ? ", " + std::to_string(r.length_m) + " m" : " (" + r.message + ")")
                << std::endl;
    }
  }
  if (stopRequested()) {
    std::cerr << "cosim: interrupted; no benchmark written\n";
    return 1;
  }
  const double total_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const PlanBenchProblem problem = describeProblem(setup, s, vehicle, inflation);
  const std::filesystem::path dir = prepareOutputDir(setup.out, "plan-bench");
  OutputManifestScope manifest(dir, "plan-bench");
  writePlanBenchFiles(dir, problem, runs, started, total_s, world);
  manifest.finish();
  return 0;
}

}  // namespace cosim
