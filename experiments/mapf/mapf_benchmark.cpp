#include "experiments/mapf/mapf_benchmark.h"

#include <algorithm>
#include <map>
#include <memory>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "core/peak_memory.h"
#include "core/stop_request.h"
#include "planning/mapf/mapf_memory_estimate.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/mapf/movingai_instance.h"
#include "planning/mapf/solution_validator.h"
#include "render/success_rate_chart.h"

namespace cosim {

namespace {

// The parameters of one planner: "key=value" for all, "PLANNER.key=value" for that one.
ParamSet plannerParams(const std::vector<std::string>& sets, const std::string& planner,
                       const std::vector<std::string>& planners) {
  ParamSet p("command line");
  for (const std::string& s : sets) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("command line", setAssignmentPlace(s), "expected key=value");
    std::string key = s.substr(0, eq);
    const auto dot = key.find('.');
    if (dot != std::string::npos) {
      const std::string owner = key.substr(0, dot);
      if (std::find(planners.begin(), planners.end(), owner) == planners.end())
        throw InputError("command line", setAssignmentPlace(s),
                         "'" + owner + "' is not one of the planners given with --planner");
      if (owner != planner) continue;
      key = key.substr(dot + 1);
    }
    p.set(key, s.substr(eq + 1), setAssignmentPlace(s));
  }
  return p;
}

// Everything a benchmark needs, read and checked before the first run: every piece of bad
// input is found before any time is spent.
struct BenchmarkInputs {
  std::vector<std::unique_ptr<MapfPlanner>> planners;
  OccupancyGrid map;
  std::vector<std::vector<MovingAIScenarioLine>> lines;  // per scenario file
  std::vector<std::string> notes;                        // for benchmark.md
};

BenchmarkInputs readInputs(const MapfBenchmarkSetup& s) {
  BenchmarkInputs in;
  for (const std::string& name : s.planners) {
    if (std::count(s.planners.begin(), s.planners.end(), name) > 1)
      throw InputError("command line", "--planner", "'" + name + "' is named twice");
    ParamSet p = plannerParams(s.sets, name, s.planners);
    in.planners.push_back(makeMapfPlanner(name, p));
  }
  in.map = readMovingAIMap(s.map);
  for (const Cell& c : s.extra_blocked) {
    if (!in.map.inside(c))
      throw InputError("command line", "--block " + std::to_string(c.x) + "," + std::to_string(c.y),
                       "off the map");
    in.map.setBlocked(c, true);
  }
  std::map<int, std::vector<std::string>> short_files;  // agents -> files with that few
  int largest = 0;
  for (const std::string& f : s.scens) {
    in.lines.push_back(readMovingAIScenario(f));
    const int n = static_cast<int>(in.lines.back().size());
    largest = std::max(largest, n);
    if (n < s.counts.back()) short_files[n].push_back(fileStem(f));
  }
  for (const auto& [n, files] : short_files) {
    std::string names;
    for (const auto& f : files) names += (names.empty() ? "" : ", ") + f;
    in.notes.push_back(names + (files.size() == 1 ? " has " : " have ") + std::to_string(n) +
                       " agents: larger counts were not run on " +
                       (files.size() == 1 ? "it." : "them."));
  }
  if (largest < s.counts.front())
    throw InputError(s.scens.front(), "",
                     "has " + std::to_string(largest) + " scenario lines, fewer than the " +
                         std::to_string(s.counts.front()) + " agents asked for");
  // Instances checked up front too (a shared start or goal is bad input, not a failure).
  for (std::size_t k = 0; k < s.scens.size(); ++k) {
    const int n = std::min<int>(s.counts.back(), static_cast<int>(in.lines[k].size()));
    if (n < s.counts.front()) continue;
    const MapfInstance largest_instance =
        mapfInstanceFromScenario(in.map, in.lines[k], n, s.connectivity, s.map, s.scens[k]);
    for (const std::string& name : s.planners)
      checkMapfTableMemory(largest_instance, name, s.scens[k]);
  }
  return in;
}

// One planner on one instance, its solution checked by the independent validator.
void runOne(MapfPlanner& planner, const MapfInstance& inst, const MapfBenchmarkSetup& s,
            MapfBenchmarkRow& r) {
  MapfQuery query;
  query.instance = &inst;
  query.time_limit_s = s.time_limit_s;
  query.seed = s.seed;
  const MapfResult result = planner.solve(query, StopToken::untimed(s.stop));
  const MapfValidation check =
      result.paths.empty() ? MapfValidation{} : validateMapfSolution(inst, result.paths);
  r.success = result.success && check.valid();
  r.status = r.success ? MapfRunStatus::Solved : MapfRunStatus::Failed;
  r.time_ms = result.time_ms;
  r.conflicts = static_cast<int>(check.conflicts.size());
  r.message = result.message;
  for (const char* key : {"distance_table_mb", "search_memory_mb"})
    if (const auto it = result.counters.find(key); it != result.counters.end())
      r.table_mb += it->second;
  r.peak_rss_mb = static_cast<double>(peakResidentBytes()) / (1 << 20);
  if (result.success && !check.valid()) r.message = "invalid solution";
  if (!r.success) return;
  r.sum_of_costs = sumOfCosts(result.paths);
  r.makespan = makespan(result.paths);
  const auto first = result.counters.find("first_sum_of_costs");
  if (first != result.counters.end()) {
    r.anytime = true;
    r.first_cost = static_cast<long>(first->second);
    r.first_solution_ms = result.counters.at("first_solution_ms");
  }
}

void writeFiles(const MapfBenchmarkSetup& s, const std::vector<MapfBenchmarkRow>& rows,
                const std::vector<std::string>& notes, MapfBenchmarkOutcome& outcome) {
  const MapfBenchmarkTally t = tallyMapfBenchmark(rows);
  writeFileAtomically(outcome.out_dir / "benchmark.csv", mapfBenchmarkCsv(s.map, rows));
  writeFileAtomically(outcome.out_dir / "success_rate.csv", mapfSuccessRateCsv(s, t));
  std::vector<SuccessRateSeries> series;
  for (const std::string& p : s.planners) {
    SuccessRateSeries& line = series.emplace_back();
    line.name = p;
    for (const int n : s.counts)
      if (const auto it = t.find({p, n}); it != t.end())
        line.points.emplace_back(n, 100.0 * it->second.second / it->second.first);
  }
  writeSuccessRateChart(series,
                        fileStem(s.map) + ": solved within " + fixedDigits(s.time_limit_s, 1) +
                            " s (" + std::to_string(s.scens.size()) + " scenario file" +
                            (s.scens.size() == 1 ? ")" : "s)"),
                        outcome.out_dir / "success_rate");
  outcome.summary_markdown = mapfBenchmarkMarkdown(s, rows, t, notes);
  writeFileAtomically(outcome.out_dir / "benchmark.md", outcome.summary_markdown);
}

}  // namespace

MapfBenchmarkOutcome runMapfBenchmark(const MapfBenchmarkSetup& s,
                                      const MapfBenchmarkProgress& progress) {
  const BenchmarkInputs in = readInputs(s);
  // The files an earlier benchmark wrote are replaced only if cosim can prove it wrote them
  // (core/output_manifest.h): anything else under their names refuses it before it runs.
  if (!s.out.empty())
    for (const auto& p :
         matchingOutputs(s.out, {"benchmark.csv", "benchmark.md", "success_rate.*"}))
      requireCosimOutput(p, "--out");
  MapfBenchmarkOutcome outcome;
  outcome.out_dir = prepareOutputDir(s.out, "mapf-benchmark");
  OutputManifestScope manifest(outcome.out_dir, "mapf");
  const auto stopped = [&] { return stopRequested() || (s.stop != nullptr && s.stop->load()); };

  std::size_t total = 0;
  for (const int n : s.counts)
    for (const auto& l : in.lines) total += n <= static_cast<int>(l.size()) ? s.planners.size() : 0;
  std::vector<MapfBenchmarkRow> rows;
  std::map<std::pair<std::string, std::string>, int> failed_at;  // (planner, scen) -> count
  std::size_t done = 0;
  for (const int n : s.counts) {
    for (std::size_t k = 0; k < s.scens.size(); ++k) {
      if (n > static_cast<int>(in.lines[k].size())) continue;
      const MapfInstance inst =
          mapfInstanceFromScenario(in.map, in.lines[k], n, s.connectivity, s.map, s.scens[k]);
      for (std::size_t p = 0; p < in.planners.size(); ++p) {
        if (stopped()) {
          outcome.interrupted = true;
          return outcome;
        }
        MapfBenchmarkRow r;
        r.scen = s.scens[k];
        r.planner = s.planners[p];
        r.agents = n;
        ++done;
        const auto failed = failed_at.find({r.planner, r.scen});
        if (!s.keep_going && failed != failed_at.end()) {
          r.status = MapfRunStatus::Skipped;
          r.message = "not run: failed at " + std::to_string(failed->second) + " agents";
          rows.push_back(r);
          continue;
        }
        runOne(*in.planners[p], inst, s, r);
        if (stopped()) continue;  // a run cut short is no result: reported at the next check
        if (!r.success) failed_at[{r.planner, r.scen}] = n;
        if (progress) progress(done, total, r);
        rows.push_back(r);
      }
    }
  }
  // A stop during the last run: nothing that looks finished.
  if (stopped()) {
    outcome.interrupted = true;
    return outcome;
  }
  writeFiles(s, rows, in.notes, outcome);
  manifest.finish();
  return outcome;
}

}  // namespace cosim
