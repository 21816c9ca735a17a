#include "cli/mapf_benchmark.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>

#include "cli/lacam_published_results.h"
#include "core/atomic_file.h"
#include "core/output_files.h"
#include "core/input_error.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/mapf/movingai_instance.h"
#include "planning/mapf/solution_validator.h"
#include "render/success_rate_chart.h"

namespace cosim::cli {

namespace {

struct Row {
  std::string scen, planner;
  int agents = 0;
  std::string status;  // solved, failed, skipped
  bool success = false;
  long sum_of_costs = 0;
  int makespan = 0;
  double time_ms = 0.0;
  bool anytime = false;  // the planner reported a first solution (LaCAM*)
  double first_solution_ms = 0.0;
  long first_cost = 0;
  int conflicts = 0;
  std::string message;
};

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string stem(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

int parseCount(const std::string& text, const std::string& whole) {
  std::size_t used = 0;
  long v = 0;
  try {
    v = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || v < 1 || v > 1'000'000)
    throw InputError("command line", "--agents " + whole,
                     "expected N or START:STOP:STEP with whole numbers from 1 to 1000000");
  return static_cast<int>(v);
}

// The parameters of one planner: "key=value" for all, "PLANNER.key=value" for that one.
ParamSet plannerParams(const std::vector<std::string>& sets, const std::string& planner,
                       const std::vector<std::string>& planners) {
  ParamSet p("command line");
  for (const std::string& s : sets) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("command line", "--set " + s, "expected key=value");
    std::string key = s.substr(0, eq);
    const auto dot = key.find('.');
    if (dot != std::string::npos) {
      const std::string owner = key.substr(0, dot);
      if (std::find(planners.begin(), planners.end(), owner) == planners.end())
        throw InputError("command line", "--set " + s,
                         "'" + owner + "' is not one of the planners given with --planner");
      if (owner != planner) continue;
      key = key.substr(dot + 1);
    }
    p.set(key, s.substr(eq + 1), "--set " + s);
  }
  return p;
}

std::string csvOf(const std::string& map, const std::vector<Row>& rows) {
  std::string csv =
      "map,scen,planner,agents,status,success,sum_of_costs,makespan,time_ms,first_solution_ms,"
      "first_cost,final_cost,conflicts,message\n";
  for (const Row& r : rows) {
    const bool run = r.status != "skipped";
    csv += csvField(stem(map)) + "," + csvField(stem(r.scen)) + "," + r.planner + "," +
           std::to_string(r.agents) + "," + r.status + "," + (r.success ? "1" : "0") + "," +
           (r.success ? std::to_string(r.sum_of_costs) : "") + "," +
           (r.success ? std::to_string(r.makespan) : "") + "," + (run ? fixed(r.time_ms, 3) : "") +
           "," + (r.success && r.anytime ? fixed(r.first_solution_ms, 3) : "") + "," +
           (r.success && r.anytime ? std::to_string(r.first_cost) : "") + "," +
           (r.success && r.anytime ? std::to_string(r.sum_of_costs) : "") + "," +
           (run ? std::to_string(r.conflicts) : "") + "," + csvField(r.message) + "\n";
  }
  return csv;
}

// Per planner and count: runs and solved runs (skipped runs count as not solved).
using Tally = std::map<std::pair<std::string, int>, std::pair<int, int>>;

Tally tally(const std::vector<Row>& rows) {
  Tally t;
  for (const Row& r : rows) {
    auto& [runs, solved] = t[{r.planner, r.agents}];
    ++runs;
    solved += r.success ? 1 : 0;
  }
  return t;
}

std::string successRateCsv(const MapfBenchmarkSetup& s, const Tally& t) {
  std::string csv = "planner,agents,instances,solved,success_rate_percent\n";
  for (const std::string& p : s.planners)
    for (const int n : s.counts) {
      const auto it = t.find({p, n});
      if (it == t.end()) continue;
      const auto [runs, solved] = it->second;
      csv += p + "," + std::to_string(n) + "," + std::to_string(runs) + "," +
             std::to_string(solved) + "," + fixed(100.0 * solved / runs, 1) + "\n";
    }
  return csv;
}

std::string summaryMarkdown(const MapfBenchmarkSetup& s, const std::vector<Row>& rows,
                            const Tally& t, const std::vector<std::string>& notes) {
  const std::string map = stem(s.map);
  std::string scens;
  for (const auto& f : s.scens) scens += (scens.empty() ? "" : ", ") + stem(f);
  std::string md = "# MAPF benchmark: " + map + "\n\n" + "Scenarios: " + scens +
                   ". Agents: " + std::to_string(s.counts.front()) + " to " +
                   std::to_string(s.counts.back()) + " (" + std::to_string(s.counts.size()) +
                   " counts). Time limit " + fixed(s.time_limit_s, 1) + " s per run, " +
                   std::to_string(s.connectivity) + "-connected, seed " + std::to_string(s.seed) +
                   ". Solved = the independent validator accepts the paths. SOC = sum of arrival "
                   "times (CONTRACT.md); every move and wait costs one step.";
  if (!s.keep_going)
    md +=
        " A planner that failed on a scenario was not run there at larger counts (`skipped`, "
        "counted as not solved).";
  md += "\n\n";
  for (const auto& n : notes) md += "- " + n + "\n";
  if (!notes.empty()) md += "\n";

  // CBS is optimal: on instances both solve, its sum of costs is the reference.
  std::map<std::pair<std::string, int>, long> cbs_soc;
  for (const Row& r : rows)
    if (r.planner == "cbs" && r.success) cbs_soc[{r.scen, r.agents}] = r.sum_of_costs;

  md +=
      "| planner | runs | solved | solved every run up to N agents | mean time of solved (ms) | "
      "SOC / CBS where both solved | CBS SOC above it |\n|---|---|---|---|---|---|---|\n";
  for (const std::string& p : s.planners) {
    int runs = 0, solved = 0, above = 0;
    double time = 0.0, soc = 0.0, cbs = 0.0;
    for (const Row& r : rows) {
      if (r.planner != p) continue;
      ++runs;
      if (!r.success) continue;
      ++solved;
      time += r.time_ms;
      const auto it = cbs_soc.find({r.scen, r.agents});
      if (it != cbs_soc.end() && p != "cbs") {
        soc += static_cast<double>(r.sum_of_costs);
        cbs += static_cast<double>(it->second);
        above += it->second > r.sum_of_costs ? 1 : 0;
      }
    }
    int up_to = 0;
    for (const int n : s.counts) {
      const auto it = t.find({p, n});
      if (it == t.end()) continue;
      if (it->second.second != it->second.first) break;
      up_to = n;
    }
    md += "| " + p + " | " + std::to_string(runs) + " | " + std::to_string(solved) + " | " +
          std::to_string(up_to) + " | " + (solved ? fixed(time / solved, 1) : "-") + " | " +
          (cbs > 0 ? fixed(soc / cbs, 3) : "-") + " | " + (cbs > 0 ? std::to_string(above) : "-") +
          " |\n";
  }

  md += "\n## Success rate (%) by agents\n\n| agents |";
  for (const auto& p : s.planners) md += " " + p + " |";
  md += "\n|---|";
  for (std::size_t i = 0; i < s.planners.size(); ++i) md += "---|";
  md += "\n";
  for (const int n : s.counts) {
    bool any = false;
    std::string line = "| " + std::to_string(n) + " |";
    for (const auto& p : s.planners) {
      const auto it = t.find({p, n});
      any = any || it != t.end();
      line += it == t.end() ? " - |"
                            : " " + fixed(100.0 * it->second.second / it->second.first, 0) + " |";
    }
    if (any) md += line + "\n";
  }

  // Anytime planners (they report a first solution): how much the search improved it.
  for (const std::string& p : s.planners) {
    double first = 0, final = 0, first_ms = 0;
    int k = 0;
    for (const Row& r : rows)
      if (r.planner == p && r.success && r.anytime)
        first += static_cast<double>(r.first_cost), final += static_cast<double>(r.sum_of_costs),
            first_ms += r.first_solution_ms, ++k;
    if (k == 0) continue;
    md += "\n" + p + " (first and final solution): over its " + std::to_string(k) +
          " solved runs, mean time to the first solution " + fixed(first_ms / k, 1) +
          " ms; final SOC / first SOC " + fixed(final / first, 3) + ".\n";
  }

  md += "\n" + lacamStarPublishedMarkdown(map);
  if (std::find(s.planners.begin(), s.planners.end(), "lacam") != s.planners.end()) {
    int runs = 0, solved = 0, in_10s = 0;
    for (const Row& r : rows)
      if (r.planner == "lacam") {
        ++runs;
        solved += r.success ? 1 : 0;
        in_10s += r.success && r.first_solution_ms <= 10000.0 ? 1 : 0;
      }
    md += "\nOurs, lacam on this map: " + std::to_string(solved) + " of " + std::to_string(runs) +
          " runs solved (" + fixed(100.0 * solved / runs, 1) +
          " %), the first solution within 10 s in " + std::to_string(in_10s) + " (" +
          fixed(100.0 * in_10s / runs, 1) + " %).\n";
  }
  return md;
}

}  // namespace

std::vector<int> parseAgentCounts(const std::string& text) {
  const auto first = text.find(':');
  if (first == std::string::npos) return {parseCount(text, text)};
  const auto second = text.find(':', first + 1);
  if (second == std::string::npos || text.find(':', second + 1) != std::string::npos)
    throw InputError("command line", "--agents " + text, "expected N or START:STOP:STEP");
  const int start = parseCount(text.substr(0, first), text);
  const int stop = parseCount(text.substr(first + 1, second - first - 1), text);
  const int step = parseCount(text.substr(second + 1), text);
  if (stop < start) throw InputError("command line", "--agents " + text, "STOP is below START");
  if ((stop - start) / step >= 10000)
    throw InputError("command line", "--agents " + text, "more than 10000 agent counts");
  std::vector<int> counts;
  for (int n = start; n <= stop; n += step) counts.push_back(n);
  return counts;
}

int runMapfBenchmark(const MapfBenchmarkSetup& s) {
  // Everything that can be bad input is checked before the first run.
  std::vector<std::unique_ptr<MapfPlanner>> planners;
  for (const std::string& name : s.planners) {
    if (std::count(s.planners.begin(), s.planners.end(), name) > 1)
      throw InputError("command line", "--planner", "'" + name + "' is named twice");
    ParamSet p = plannerParams(s.sets, name, s.planners);
    planners.push_back(makeMapfPlanner(name, p));
  }
  OccupancyGrid map = readMovingAIMap(s.map);
  for (const Cell& c : s.extra_blocked) {
    if (!map.inside(c))
      throw InputError("command line", "--block " + std::to_string(c.x) + "," + std::to_string(c.y),
                       "off the map");
    map.setBlocked(c, true);
  }
  std::vector<std::vector<MovingAIScenarioLine>> lines;
  std::map<int, std::vector<std::string>> short_files;  // agents -> files with that few
  int largest = 0;
  for (const std::string& f : s.scens) {
    lines.push_back(readMovingAIScenario(f));
    const int n = static_cast<int>(lines.back().size());
    largest = std::max(largest, n);
    if (n < s.counts.back()) short_files[n].push_back(stem(f));
  }
  std::vector<std::string> notes;
  for (const auto& [n, files] : short_files) {
    std::string names;
    for (const auto& f : files) names += (names.empty() ? "" : ", ") + f;
    notes.push_back(names + (files.size() == 1 ? " has " : " have ") + std::to_string(n) +
                    " agents: larger counts were not run on " +
                    (files.size() == 1 ? "it." : "them."));
  }
  if (largest < s.counts.front())
    throw InputError(s.scens.front(), "",
                     "has " + std::to_string(largest) + " scenario lines, fewer than the " +
                         std::to_string(s.counts.front()) + " agents asked for");
  // Instances checked up front too (a shared start or goal is bad input, not a failure).
  for (std::size_t k = 0; k < s.scens.size(); ++k) {
    const int n = std::min<int>(s.counts.back(), static_cast<int>(lines[k].size()));
    if (n >= s.counts.front())
      mapfInstanceFromScenario(map, lines[k], n, s.connectivity, s.map, s.scens[k]);
  }

  const std::filesystem::path out_dir = prepareOutputDir(s.out, "mapf-benchmark");

  std::size_t total = 0;
  for (const int n : s.counts)
    for (const auto& l : lines) total += n <= static_cast<int>(l.size()) ? s.planners.size() : 0;
  std::vector<Row> rows;
  std::map<std::pair<std::string, std::string>, int> failed_at;  // (planner, scen) -> count
  std::size_t done = 0;
  for (const int n : s.counts) {
    for (std::size_t k = 0; k < s.scens.size(); ++k) {
      if (n > static_cast<int>(lines[k].size())) continue;
      const MapfInstance inst =
          mapfInstanceFromScenario(map, lines[k], n, s.connectivity, s.map, s.scens[k]);
      for (std::size_t p = 0; p < planners.size(); ++p) {
        if (s.stop != nullptr && s.stop->load()) {
          std::cerr << "cosim: interrupted; " << out_dir.string()
                    << " holds no finished benchmark\n";
          return 1;
        }
        Row r;
        r.scen = s.scens[k];
        r.planner = s.planners[p];
        r.agents = n;
        ++done;
        const auto failed = failed_at.find({r.planner, r.scen});
        if (!s.keep_going && failed != failed_at.end()) {
          r.status = "skipped";
          r.message = "not run: failed at " + std::to_string(failed->second) + " agents";
          rows.push_back(r);
          continue;
        }
        MapfQuery query;
        query.instance = &inst;
        query.time_limit_s = s.time_limit_s;
        query.seed = s.seed;
        query.stop = s.stop;
        const MapfResult result = planners[p]->solve(query);
        if (s.stop != nullptr && s.stop->load()) continue;  // reported at the next run
        const MapfValidation check =
            result.paths.empty() ? MapfValidation{} : validateMapfSolution(inst, result.paths);
        r.success = result.success && check.valid();
        r.status = r.success ? "solved" : "failed";
        r.time_ms = result.time_ms;
        r.conflicts = static_cast<int>(check.conflicts.size());
        r.message = result.message;
        if (result.success && !check.valid()) r.message = "invalid solution";
        if (r.success) {
          r.sum_of_costs = sumOfCosts(result.paths);
          r.makespan = makespan(result.paths);
          const auto first = result.counters.find("first_sum_of_costs");
          if (first != result.counters.end()) {
            r.anytime = true;
            r.first_cost = static_cast<long>(first->second);
            r.first_solution_ms = result.counters.at("first_solution_ms");
          }
        } else {
          failed_at[{r.planner, r.scen}] = n;
        }
        std::cerr << "cosim: [" << done << "/" << total << "] " << r.planner << ", " << n
                  << " agents, " << stem(r.scen) << ": "
                  << (r.success ? "solved, SOC " + std::to_string(r.sum_of_costs) : r.status)
                  << ", " << fixed(r.time_ms, 1) << " ms"
                  << (r.message.empty() ? "" : " (" + r.message + ")") << std::endl;
        rows.push_back(r);
      }
    }
  }

  const Tally t = tally(rows);
  writeFileAtomically(out_dir / "benchmark.csv", csvOf(s.map, rows));
  writeFileAtomically(out_dir / "success_rate.csv", successRateCsv(s, t));
  std::vector<SuccessRateSeries> series;
  for (const std::string& p : s.planners) {
    SuccessRateSeries& line = series.emplace_back();
    line.name = p;
    for (const int n : s.counts)
      if (const auto it = t.find({p, n}); it != t.end())
        line.points.emplace_back(n, 100.0 * it->second.second / it->second.first);
  }
  writeSuccessRateChart(series,
                        stem(s.map) + ": solved within " + fixed(s.time_limit_s, 1) + " s (" +
                            std::to_string(s.scens.size()) + " scenario file" +
                            (s.scens.size() == 1 ? ")" : "s)"),
                        out_dir / "success_rate");
  const std::string md = summaryMarkdown(s, rows, t, notes);
  writeFileAtomically(out_dir / "benchmark.md", md);
  std::cout << md << "\nwritten: " << out_dir.string()
            << "/benchmark.csv, success_rate.csv, success_rate.png, success_rate.svg, "
               "benchmark.md\n";
  return 0;
}

}  // namespace cosim::cli
