// cosim_bench_ompl: our sampling planners against OMPL 1.5.2 in the same run, on the same exact
// collision world (OMPL gets our CollisionWorld through a StateValidityChecker and a
// MotionValidator, so both sides pay the same for collision checks), on three 3D worlds:
// open, a cluttered forest and a narrow passage.
//   - RRT and RRT-Connect: time to the first solution (median over seeds) and success rate;
//   - RRT* and Informed RRT*: path length after a fixed time, and success rate.
// Targets: our time to first solution <= OMPL's, our cost at fixed time <= OMPL's, every world.
// Usage: cosim_bench_ompl [--quick] [--seeds N] [--time SECONDS]
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "experiments/bench/ompl/exact_motion_checks.h"
#include "planning/planner_registry.h"
#include "planning/sampling/collision_world.h"

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

using cosim::CollisionWorld;
using cosim::Obstacle;
using cosim::ObstacleType;
using cosim::World;

constexpr double kInflation = 0.3;  // vehicle radius + margin, both sides
constexpr double kGoalBias = 0.05;  // OMPL's default, set on both sides

struct BenchWorld {
  std::string name;
  World world;
  Eigen::Vector3d start, goal;
  double step;  // maximum edge length: our `step`, OMPL's range
};

Obstacle box(Eigen::Vector3d pos, Eigen::Vector3d size, double yaw = 0) {
  Obstacle o;
  o.pos = pos;
  o.size = size;
  o.yaw_deg = yaw;
  return o;
}

std::vector<BenchWorld> benchWorlds() {
  std::vector<BenchWorld> worlds;
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  {  // Open: 50 x 50 x 20 m with 15 scattered blocks and balls.
    BenchWorld b{"open", {}, {2, 2, 2}, {48, 48, 18}, 4.0};
    b.world.bounds_min = {0, 0, 0};
    b.world.bounds_max = {50, 50, 20};
    for (int i = 0; i < 15; ++i) {
      Obstacle o = box({8 + 34 * u(rng), 8 + 34 * u(rng), 20 * u(rng)},
                       {2 + 4 * u(rng), 2 + 4 * u(rng), 2 + 6 * u(rng)}, 90 * u(rng));
      if (i % 2) o.type = ObstacleType::Sphere, o.radius = 1 + 2 * u(rng);
      b.world.obstacles.push_back(o);
    }
    worlds.push_back(b);
  }
  {  // Forest: 50 x 50 x 10 m, 600 full-height trunks (radius 0.3-0.8 m) and 40 crowns.
    BenchWorld b{"forest", {}, {1, 1, 2}, {49, 49, 5}, 2.0};
    b.world.bounds_min = {0, 0, 0};
    b.world.bounds_max = {50, 50, 10};
    for (int i = 0; i < 640; ++i) {
      Obstacle o;
      const Eigen::Vector3d at(3 + 44 * u(rng), 3 + 44 * u(rng), 0);
      if (i < 600) {
        o.type = ObstacleType::Cylinder;
        o.radius = 0.3 + 0.5 * u(rng);
        o.height = 10;
        o.pos = at + Eigen::Vector3d(0, 0, 5);
      } else {
        o.type = ObstacleType::Sphere;
        o.radius = 1.0 + 1.5 * u(rng);
        o.pos = at + Eigen::Vector3d(0, 0, 4 + 5 * u(rng));
      }
      b.world.obstacles.push_back(o);
    }
    worlds.push_back(b);
  }
  {  // Narrow passage: a wall across the 30 x 30 x 10 m box with one 1.6 m square window
     // (1.0 m after inflation), away from the straight line between start and goal.
    BenchWorld b{"narrow", {}, {3, 15, 5}, {27, 15, 5}, 2.0};
    b.world.bounds_min = {0, 0, 0};
    b.world.bounds_max = {30, 30, 10};
    const double wx = 15, t = 0.6, hy = 24, hz = 2.5, h = 0.8;  // window centre (y, z), half size
    b.world.obstacles = {
        box({wx, (hy - h) / 2, 5}, {t, hy - h, 10}),                 // y below the window
        box({wx, (hy + h + 30) / 2, 5}, {t, 30 - hy - h, 10}),       // y above the window
        box({wx, hy, (hz - h) / 2}, {t, 2 * h, hz - h}),             // under the window
        box({wx, hy, (hz + h + 10) / 2}, {t, 2 * h, 10 - hz - h})};  // over the window
    worlds.push_back(b);
  }
  return worlds;
}

struct Outcome {
  bool success = false;
  double time_ms = 0, cost = 0;
};

// ---- ours ----------------------------------------------------------------------------------

Outcome runOurs(const BenchWorld& b, const std::string& planner,
                const std::vector<std::pair<std::string, std::string>>& params, std::uint64_t seed,
                double time_limit) {
  cosim::ParamSet p("bench");
  p.set("step", std::to_string(b.step));
  for (const auto& [k, v] : params) p.set(k, v);
  auto solver = cosim::makePlanner(planner, p, "bench");
  cosim::PlanningProblem prob;
  prob.world = &b.world;
  prob.start = b.start;
  prob.goal = b.goal;
  prob.inflation = kInflation;
  prob.time_limit_s = time_limit;
  prob.seed = seed;
  const cosim::PlanResult r = solver->solve(prob, cosim::StopToken::untimed());
  return {r.success, r.time_ms, r.success ? r.path.length() : 0.0};
}

// ---- OMPL ----------------------------------------------------------------------------------

Outcome runOmpl(const BenchWorld& b, const CollisionWorld& cw, const std::string& planner,
                double time_limit) {
  auto space = std::make_shared<ob::RealVectorStateSpace>(3);
  ob::RealVectorBounds bounds(3);
  for (int i = 0; i < 3; ++i) {
    bounds.setLow(i, b.world.bounds_min[i]);
    bounds.setHigh(i, b.world.bounds_max[i]);
  }
  space->setBounds(bounds);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker(std::make_shared<cosim::omplbench::ExactValidityChecker>(si, cw));
  si->setMotionValidator(std::make_shared<cosim::omplbench::ExactMotionValidator>(si, cw));
  si->setup();
  ob::ScopedState<> start(space), goal(space);
  for (int i = 0; i < 3; ++i) start[i] = b.start[i], goal[i] = b.goal[i];
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  pdef->setStartAndGoalStates(start, goal);
  auto objective = std::make_shared<ob::PathLengthOptimizationObjective>(si);
  objective->setCostThreshold(ob::Cost(0.0));  // never "good enough": use the whole time
  pdef->setOptimizationObjective(objective);

  ob::PlannerPtr p;
  if (planner == "rrt") {
    auto q = std::make_shared<og::RRT>(si);
    q->setRange(b.step), q->setGoalBias(kGoalBias);
    p = q;
  } else if (planner == "rrt_connect") {
    auto q = std::make_shared<og::RRTConnect>(si);
    q->setRange(b.step);
    p = q;
  } else if (planner == "rrt_star") {
    auto q = std::make_shared<og::RRTstar>(si);
    q->setRange(b.step), q->setGoalBias(kGoalBias);
    p = q;
  } else {
    auto q = std::make_shared<og::InformedRRTstar>(si);
    q->setRange(b.step), q->setGoalBias(kGoalBias);
    p = q;
  }
  p->setProblemDefinition(pdef);
  p->setup();
  const auto t0 = std::chrono::steady_clock::now();
  const ob::PlannerStatus status = p->solve(ob::timedPlannerTerminationCondition(time_limit));
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  Outcome out;
  out.time_ms = ms;
  out.success = status == ob::PlannerStatus::EXACT_SOLUTION && pdef->hasExactSolution();
  if (out.success) out.cost = pdef->getSolutionPath()->as<og::PathGeometric>()->length();
  return out;
}

// ---- statistics and table -------------------------------------------------------------------

struct SampledRuns {
  int runs = 0, successes = 0;
  std::vector<double> values;  // time (first solution) or cost (fixed time) of successes
  double median() const {
    if (values.empty()) return 0.0;
    std::vector<double> v = values;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  }
  double mean() const {
    double s = 0;
    for (double x : values) s += x;
    return values.empty() ? 0.0 : s / values.size();
  }
};

struct ComparisonRow {
  std::string world, planner, metric;
  SampledRuns ours, ompl;
  bool lower_is_target;  // ours <= OMPL is the target
};

// One planner setting: the registered planner, the table's label, its parameters, and whether
// it is timed to its first solution (else: its path length after a fixed time).
struct Job {
  std::string planner, label;
  std::vector<std::pair<std::string, std::string>> params;
  bool first_solution;
};

std::vector<Job> benchJobs() {
  const std::string bias = std::to_string(kGoalBias);
  return {{"rrt", "rrt", {{"goal_bias", bias}, {"max_nodes", "10000000"}}, true},
          {"rrt",
           "rrt (goal_tolerance 0)",
           {{"goal_bias", bias}, {"goal_tolerance", "0"}, {"max_nodes", "10000000"}},
           true},
          {"rrt_connect", "rrt_connect", {{"max_nodes", "10000000"}}, true},
          {"rrt_star",
           "rrt_star",
           {{"goal_bias", bias}, {"mode", "2"}, {"rewire_radius", "0"}, {"max_nodes", "10000000"}},
           false},
          {"informed_rrt_star",
           "informed_rrt_star",
           {{"goal_bias", bias}, {"max_nodes", "10000000"}},
           false}};
}

// One job on one world over `seeds` seeds, ours and (for jobs without a variant in brackets)
// OMPL's.
ComparisonRow runJob(const BenchWorld& b, const CollisionWorld& cw, const Job& job, int seeds,
                     double first_limit, double fixed_time) {
  ComparisonRow row{
      b.name,
      job.label,
      job.first_solution ? "time to first solution [ms]" : "path length after fixed time [m]",
      {},
      {},
      true};
  const double limit = job.first_solution ? first_limit : fixed_time;
  for (int s = 0; s < seeds; ++s) {
    const Outcome o = runOurs(b, job.planner, job.params, 1 + s, limit);
    const Outcome q =
        job.label.find('(') == std::string::npos ? runOmpl(b, cw, job.planner, limit) : Outcome{};
    for (auto [summary, out] : {std::pair{&row.ours, o}, std::pair{&row.ompl, q}}) {
      ++summary->runs;
      if (!out.success) continue;
      ++summary->successes;
      summary->values.push_back(job.first_solution ? out.time_ms : out.cost);
    }
  }
  return row;
}

// The markdown table and the verdict line.
void printTable(const std::vector<ComparisonRow>& rows, int seeds, double fixed_time, bool quick) {
  std::printf(
      "Sampling planners vs OMPL 1.5.2, same exact collision world (inflation %.1f m), "
      "%d seeds, fixed time %.2f s%s\n\n",
      kInflation, seeds, fixed_time, quick ? " (quick)" : "");
  std::printf(
      "| world | planner | metric | ours median | OMPL median | ours/OMPL | ours mean | "
      "OMPL mean | ours success | OMPL success | target |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  int missed = 0, compared_rows = 0;
  for (const ComparisonRow& r : rows) {
    const bool has_ompl = r.ompl.successes > 0;
    const double ratio = has_ompl && r.ompl.median() > 0 ? r.ours.median() / r.ompl.median() : 0;
    const bool met = !has_ompl || (r.ours.successes >= r.ompl.successes && ratio <= 1.0);
    const bool compared = r.planner.find('(') == std::string::npos;
    compared_rows += compared;
    if (compared && !met) ++missed;
    auto num = [&](double v) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.3f", v);
      return compared ? std::string(buf) : std::string("-");
    };
    const std::string ompl_success =
        compared ? std::to_string(r.ompl.successes) + "/" + std::to_string(r.ompl.runs) : "-";
    std::printf("| %s | %s | %s | %.3f | %s | %s | %.3f | %s | %d/%d | %s | %s |\n",
                r.world.c_str(), r.planner.c_str(), r.metric.c_str(), r.ours.median(),
                num(r.ompl.median()).c_str(), has_ompl ? num(ratio).c_str() : "-", r.ours.mean(),
                num(r.ompl.mean()).c_str(), r.ours.successes, r.ours.runs, ompl_success.c_str(),
                compared ? (met ? "met" : "MISSED") : "(info)");
  }
  std::printf("\nTarget (ours <= OMPL and success >= OMPL's): %s on %d row(s)\n",
              missed ? "missed" : "met", missed ? missed : compared_rows);
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  int seeds = 0;
  double fixed_time = 0;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) {
      quick = true;
    } else if (!std::strcmp(argv[i], "--seeds") && i + 1 < argc) {
      seeds = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--time") && i + 1 < argc) {
      fixed_time = std::atof(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--quick] [--seeds N] [--time SECONDS]\n", argv[0]);
      return 2;
    }
  }
  if (seeds <= 0) seeds = quick ? 10 : 50;
  if (fixed_time <= 0) fixed_time = quick ? 0.05 : 0.3;
  const double first_limit = quick ? 2.0 : 10.0;
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(1);  // OMPL seeds once per process; each run continues the stream

  std::vector<ComparisonRow> rows;
  for (const BenchWorld& b : benchWorlds()) {
    const CollisionWorld cw(b.world, kInflation);
    for (const Job& job : benchJobs())
      rows.push_back(runJob(b, cw, job, seeds, first_limit, fixed_time));
  }
  printTable(rows, seeds, fixed_time, quick);
  return 0;
}
