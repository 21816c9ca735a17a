#include "experiments/bench/plan_bench_files.h"

#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <thread>

#include "experiments/bench/ompl/ompl_planner_runs.h"
#include "experiments/bench/ompl_benchmark_log.h"
#include "core/atomic_file.h"
#include "experiments/reproduce/report_files.h"
#include "render/plan_bench_chart.h"

namespace cosim {

namespace {

using reproduce::fixed;

std::string isoUtc(std::chrono::system_clock::time_point t) {
  const std::time_t seconds = std::chrono::system_clock::to_time_t(t);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &utc);
  return buf;
}

std::string hostName() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0 || buf[0] == '\0') return "UNKNOWN";
  std::string host = buf;
  for (char& c : host)
    if (c == ' ') c = '_';  // the reader keeps the line's last word
  return host;
}

// The processor's model name (the first of /proc/cpuinfo) and how many threads it runs.
std::string cpuDescription() {
  std::ifstream in("/proc/cpuinfo");
  std::string model;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  return (model.empty() ? std::string("unknown processor") : model) + ", " +
         std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
}

std::string setupText(const PlanBenchProblem& p, const CollisionWorld& world) {
  auto point = [](const Eigen::Vector3d& v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%g, %g, %g)", v.x(), v.y(), v.z());
    return std::string(buf);
  };
  return "cosim plan-bench on " + p.scenario + "\nstart " + p.start + ", goal " + p.goal + ", " +
         std::to_string(p.segments) + " segment(s), straight line " + fixed(p.straight_line_m, 3) +
         " m\n" + std::to_string(p.obstacles) + " obstacles inflated by " +
         fixed(p.inflation_m, 3) +
         " m, exact point and segment tests (cosim CollisionWorld) for every planner\n" +
         "sampling region " + point(world.validMin()) + " to " + point(world.validMax()) + "\n" +
         "solution length: Euclidean length of the returned path, not simplified\n";
}

OmplLogExperiment logExperiment(const PlanBenchProblem& p, const std::vector<PlanBenchRun>& runs,
                                std::chrono::system_clock::time_point started, double total_s,
                                const CollisionWorld& world) {
  OmplLogExperiment e;
  e.version = omplbench::omplVersion();
  e.name = "cosim-plan-bench";
  e.properties = {{"scenario STRING", p.scenario},
                  {"inflation_m REAL", fixed(p.inflation_m, 6)},
                  {"obstacles INTEGER", std::to_string(p.obstacles)},
                  {"straight_line_m REAL", fixed(p.straight_line_m, 6)}};
  e.host = hostName();
  e.start_time = isoUtc(started);
  e.setup = setupText(p, world);
  e.cpu = cpuDescription();
  e.seed = 1;  // runs use seeds 1..N ("seed" of each run)
  e.time_limit_s = p.time_limit_s;
  e.runs_per_planner = p.runs;
  e.total_s = total_s;
  for (const PlanBenchRun& r : runs) {
    if (e.planners.empty() || e.planners.back().name != r.planner)
      e.planners.push_back({r.planner, {}, {}});
    OmplLogPlanner& planner = e.planners.back();
    if (!r.params.empty()) planner.common = r.params;
    std::map<std::string, std::string> row = {
        {"time REAL", fixed(r.time_ms / 1000.0, 6)},
        {"solved BOOLEAN", r.solved ? "1" : "0"},
        {"status ENUM", std::to_string(r.status)},
        {"approximate solution BOOLEAN",
         r.status == omplbench::omplStatusApproximate() ? "1" : "0"},
        {"seed INTEGER", std::to_string(r.seed)},
        {"graph states INTEGER", r.graph_states >= 0 ? fixed(r.graph_states, 0) : ""},
        {"solution length REAL", r.solved ? fixed(r.length_m, 6) : ""},
        {"solution segments INTEGER", r.solved ? std::to_string(r.waypoints - 1) : ""},
        {"correct solution BOOLEAN", r.solved ? (r.path_clear ? "1" : "0") : ""}};
    planner.runs.push_back(row);
  }
  return e;
}

std::vector<PlannerBenchSamples> chartSamples(const std::vector<PlannerSummary>& summaries) {
  std::vector<PlannerBenchSamples> out;
  for (const PlannerSummary& s : summaries)
    out.push_back({s.planner, s.runs, s.solved, s.times_ms, s.lengths_m});
  return out;
}

}  // namespace

void writePlanBenchFiles(const std::filesystem::path& dir, const PlanBenchProblem& problem,
                         const std::vector<PlanBenchRun>& runs,
                         std::chrono::system_clock::time_point started, double total_s,
                         const CollisionWorld& world) {
  const std::vector<PlannerSummary> summaries = summarizePlanBench(runs);
  const std::string md = planBenchSummaryMarkdown(problem, summaries);
  // The figure first: gnuplot is what most likely fails, and then nothing else is written.
  writePlanBenchChart(chartSamples(summaries),
                      problem.scenario + ": " + std::to_string(problem.runs) + " runs, " +
                          fixed(problem.time_limit_s, 2) + " s each",
                      dir / "plan_bench");
  writeFileAtomically(dir / "runs.csv", planBenchRunsCsv(runs));
  writeFileAtomically(dir / "summary.csv", planBenchSummaryCsv(summaries));
  writeFileAtomically(dir / "plan-bench.log",
                      omplBenchmarkLog(logExperiment(problem, runs, started, total_s, world),
                                       omplbench::omplStatusNames()));
  writeFileAtomically(dir / "summary.md", md);
  std::cout << md << "\nwritten: " << dir.string()
            << "/runs.csv, summary.csv, summary.md, plan-bench.log, plan_bench.png, "
               "plan_bench.svg\n";
}

}  // namespace cosim
