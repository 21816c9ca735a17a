#include "experiments/mapf/mapf_benchmark_report.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "core/csv_text.h"
#include "experiments/mapf/lacam_published_results.h"

namespace cosim {

std::string fixedDigits(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string fileStem(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

const char* mapfRunStatusName(MapfRunStatus status) {
  switch (status) {
    case MapfRunStatus::Solved:
      return "solved";
    case MapfRunStatus::Failed:
      return "failed";
    case MapfRunStatus::Skipped:
      return "skipped";
  }
  return "failed";
}

std::string mapfBenchmarkCsv(const std::string& map, const std::vector<MapfBenchmarkRow>& rows) {
  std::string csv =
      "map,scen,planner,agents,status,success,sum_of_costs,makespan,time_ms,first_solution_ms,"
      "first_cost,final_cost,conflicts,table_mb,peak_rss_mb,message\n";
  for (const MapfBenchmarkRow& r : rows) {
    const bool run = r.status != MapfRunStatus::Skipped;
    csv += csvField(fileStem(map)) + "," + csvField(fileStem(r.scen)) + "," + r.planner + "," +
           std::to_string(r.agents) + "," + mapfRunStatusName(r.status) + "," +
           (r.success ? "1" : "0") + "," + (r.success ? std::to_string(r.sum_of_costs) : "") + "," +
           (r.success ? std::to_string(r.makespan) : "") + "," +
           (run ? fixedDigits(r.time_ms, 3) : "") + "," +
           // A planner that is not anytime: its one solution is its first.
           (r.success ? fixedDigits(r.anytime ? r.first_solution_ms : r.time_ms, 3) : "") + "," +
           (r.success && r.anytime ? std::to_string(r.first_cost) : "") + "," +
           (r.success && r.anytime ? std::to_string(r.sum_of_costs) : "") + "," +
           (run ? std::to_string(r.conflicts) : "") + "," +
           (run ? fixedDigits(r.table_mb, 1) : "") + "," +
           (run ? fixedDigits(r.peak_rss_mb, 1) : "") + "," + csvField(r.message) + "\n";
  }
  return csv;
}

MapfBenchmarkTally tallyMapfBenchmark(const std::vector<MapfBenchmarkRow>& rows) {
  MapfBenchmarkTally t;
  for (const MapfBenchmarkRow& r : rows) {
    auto& [runs, solved] = t[{r.planner, r.agents}];
    ++runs;
    solved += r.success ? 1 : 0;
  }
  return t;
}

std::string mapfSuccessRateCsv(const MapfBenchmarkSetup& s, const MapfBenchmarkTally& t) {
  std::string csv = "planner,agents,instances,solved,success_rate_percent\n";
  for (const std::string& p : s.planners)
    for (const int n : s.counts) {
      const auto it = t.find({p, n});
      if (it == t.end()) continue;
      const auto [runs, solved] = it->second;
      csv += p + "," + std::to_string(n) + "," + std::to_string(runs) + "," +
             std::to_string(solved) + "," + fixedDigits(100.0 * solved / runs, 1) + "\n";
    }
  return csv;
}

namespace {

// The summary table: per planner its runs, solved runs, the largest count solved every run, its
// mean time and its sum of costs against CBS's (optimal) on the instances both solved.
std::string plannerSummaryTable(const MapfBenchmarkSetup& s,
                                const std::vector<MapfBenchmarkRow>& rows,
                                const MapfBenchmarkTally& t) {
  std::string md;
  // CBS is optimal: on instances both solve, its sum of costs is the reference.
  std::map<std::pair<std::string, int>, long> cbs_soc;
  for (const MapfBenchmarkRow& r : rows)
    if (r.planner == "cbs" && r.success) cbs_soc[{r.scen, r.agents}] = r.sum_of_costs;

  md +=
      "| planner | runs | solved | solved every run up to N agents | mean time of solved (ms) | "
      "SOC / CBS where both solved | CBS SOC above it |\n|---|---|---|---|---|---|---|\n";
  for (const std::string& p : s.planners) {
    int runs = 0, solved = 0, above = 0;
    double time = 0.0, soc = 0.0, cbs = 0.0;
    for (const MapfBenchmarkRow& r : rows) {
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
          std::to_string(up_to) + " | " + (solved ? fixedDigits(time / solved, 1) : "-") + " | " +
          (cbs > 0 ? fixedDigits(soc / cbs, 3) : "-") + " | " +
          (cbs > 0 ? std::to_string(above) : "-") + " |\n";
  }

  return md;
}

// Success rate (%) per planner and agent count.
std::string successRateTable(const MapfBenchmarkSetup& s, const MapfBenchmarkTally& t) {
  std::string md;
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
      // (appended piecewise: GCC 12 warns falsely on " " + std::string, -Wrestrict)
      if (it == t.end()) {
        line += " - |";
      } else {
        line += " ";
        line += fixedDigits(100.0 * it->second.second / it->second.first, 0) + " |";
      }
    }
    if (any) md += line + "\n";
  }

  return md;
}

// Anytime planners (they report a first solution): how much the search improved it.
std::string anytimeImprovement(const MapfBenchmarkSetup& s,
                               const std::vector<MapfBenchmarkRow>& rows) {
  std::string md;
  for (const std::string& p : s.planners) {
    double first = 0, final = 0, first_ms = 0;
    int k = 0;
    for (const MapfBenchmarkRow& r : rows)
      if (r.planner == p && r.success && r.anytime)
        first += static_cast<double>(r.first_cost), final += static_cast<double>(r.sum_of_costs),
            first_ms += r.first_solution_ms, ++k;
    if (k == 0) continue;
    md += "\n" + p + " (first and final solution): over its " + std::to_string(k) +
          " solved runs, mean time to the first solution " + fixedDigits(first_ms / k, 1) +
          " ms; final SOC / first SOC " + fixedDigits(final / first, 3) + ".\n";
  }

  return md;
}

// Ours beside LaCAM*'s published figures: lacam's solved runs and first solutions within 10 s.
std::string lacamAgainstPublished(const MapfBenchmarkSetup& s,
                                  const std::vector<MapfBenchmarkRow>& rows) {
  std::string md;
  if (std::find(s.planners.begin(), s.planners.end(), "lacam") != s.planners.end()) {
    int runs = 0, solved = 0, in_10s = 0;
    for (const MapfBenchmarkRow& r : rows)
      if (r.planner == "lacam") {
        ++runs;
        solved += r.success ? 1 : 0;
        in_10s += r.success && r.first_solution_ms <= 10000.0 ? 1 : 0;
      }
    md += "\nOurs, lacam on this map: " + std::to_string(solved) + " of " + std::to_string(runs) +
          " runs solved (" + fixedDigits(100.0 * solved / runs, 1) +
          " %), the first solution within 10 s in " + std::to_string(in_10s) + " (" +
          fixedDigits(100.0 * in_10s / runs, 1) + " %).\n";
  }
  return md;
}

}  // namespace

std::string mapfBenchmarkMarkdown(const MapfBenchmarkSetup& s,
                                  const std::vector<MapfBenchmarkRow>& rows,
                                  const MapfBenchmarkTally& t,
                                  const std::vector<std::string>& notes) {
  const std::string map = fileStem(s.map);
  std::string scens;
  for (const auto& f : s.scens) scens += (scens.empty() ? "" : ", ") + fileStem(f);
  std::string md = "# MAPF benchmark: " + map + "\n\n" + "Scenarios: " + scens +
                   ". Agents: " + std::to_string(s.counts.front()) + " to " +
                   std::to_string(s.counts.back()) + " (" + std::to_string(s.counts.size()) +
                   " counts). Time limit " + fixedDigits(s.time_limit_s, 1) + " s per run, " +
                   std::to_string(s.connectivity) + "-connected, seed " + std::to_string(s.seed) +
                   ". Solved = the independent validator accepts the paths. SOC = sum of arrival "
                   "times; every move and wait costs one step.";
  if (!s.keep_going)
    md +=
        " A planner that failed on a scenario was not run there at larger counts (`skipped`, "
        "counted as not solved).";
  md += "\n\n";
  for (const auto& n : notes) md += "- " + n + "\n";
  if (!notes.empty()) md += "\n";

  md += plannerSummaryTable(s, rows, t);
  md += successRateTable(s, t);
  md += anytimeImprovement(s, rows);
  md += "\n";
  md += lacamStarPublishedMarkdown(map);
  md += lacamAgainstPublished(s, rows);
  return md;
}

}  // namespace cosim
