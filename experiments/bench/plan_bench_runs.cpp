#include "experiments/bench/plan_bench_runs.h"

#include <algorithm>
#include <cmath>

#include "experiments/reproduce/report_files.h"
#include "core/csv_text.h"

namespace cosim {

namespace {

using reproduce::fixed;

// Time median, Q1, Q3, then length median, Q1, Q3, minimum (`none` when no run was solved).
std::string summaryCells(const PlannerSummary& s, const std::string& sep, const std::string& none) {
  const bool any = !s.lengths_m.empty();
  auto length = [&](double p) { return any ? fixed(quantile(s.lengths_m, p), 3) : none; };
  return fixed(quantile(s.times_ms, 0.5), 3) + sep + fixed(quantile(s.times_ms, 0.25), 3) + sep +
         fixed(quantile(s.times_ms, 0.75), 3) + sep + length(0.5) + sep + length(0.25) + sep +
         length(0.75) + sep + length(0.0);
}

}  // namespace

double quantile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double h = (static_cast<double>(values.size()) - 1.0) * std::clamp(p, 0.0, 1.0);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (h - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

std::vector<PlannerSummary> summarizePlanBench(const std::vector<PlanBenchRun>& runs) {
  std::vector<PlannerSummary> out;
  for (const PlanBenchRun& r : runs) {
    auto it = std::find_if(out.begin(), out.end(),
                           [&](const PlannerSummary& s) { return s.planner == r.planner; });
    if (it == out.end()) {
      out.push_back({r.planner, r.ompl, 0, 0, {}, {}});
      it = out.end() - 1;
    }
    ++it->runs;
    it->times_ms.push_back(r.time_ms);
    if (!r.solved) continue;
    ++it->solved;
    it->lengths_m.push_back(r.length_m);
  }
  return out;
}

std::string planBenchRunsCsv(const std::vector<PlanBenchRun>& runs) {
  std::string csv =
      "planner,library,seed,solved,status,time_ms,length_m,waypoints,graph_states,path_clear,"
      "message\n";
  for (const PlanBenchRun& r : runs)
    csv += r.planner + "," + (r.ompl ? "ompl" : "cosim") + "," + std::to_string(r.seed) + "," +
           (r.solved ? "1" : "0") + "," + std::to_string(r.status) + "," + fixed(r.time_ms, 3) +
           "," + (r.solved ? fixed(r.length_m, 4) : "") + "," + std::to_string(r.waypoints) + "," +
           (r.graph_states >= 0 ? fixed(r.graph_states, 0) : "") + "," +
           (r.solved ? (r.path_clear ? "1" : "0") : "") + "," + csvField(r.message) + "\n";
  return csv;
}

std::string planBenchSummaryCsv(const std::vector<PlannerSummary>& summaries) {
  std::string csv =
      "planner,library,runs,solved,success_rate_percent,time_ms_median,time_ms_q1,time_ms_q3,"
      "length_m_median,length_m_q1,length_m_q3,length_m_min\n";
  for (const PlannerSummary& s : summaries) {
    csv += s.planner + "," + (s.ompl ? "ompl" : "cosim") + "," + std::to_string(s.runs) + "," +
           std::to_string(s.solved) + "," + fixed(100.0 * s.solved / s.runs, 1) + "," +
           summaryCells(s, ",", "") + "\n";
  }
  return csv;
}

std::string planBenchSummaryMarkdown(const PlanBenchProblem& p,
                                     const std::vector<PlannerSummary>& summaries) {
  std::string md =
      "# Planner benchmark: " + p.scenario + "\n\n" + "From " + p.start + " to " + p.goal +
      (p.segments > 1 ? " (" + std::to_string(p.segments) + " segments)" : "") +
      ", straight line " + fixed(p.straight_line_m, 2) + " m; " + std::to_string(p.obstacles) +
      " obstacles grown by " + fixed(p.inflation_m, 3) + " m (vehicle radius + planner.margin). " +
      std::to_string(p.runs) + " runs per planner (seeds 1 to " + std::to_string(p.runs) + "), " +
      fixed(p.time_limit_s, 3) +
      " s per run. Time: every run's wall-clock planning time (a failed run counts "
      "its whole time). Length: Euclidean length of the path as the planner returned "
      "it, solved runs only; OMPL's paths are not simplified, ours are shortcut only "
      "if the scenario sets planner.shortcut.\n\n";
  md +=
      "| planner | library | solved | success (%) | time median (ms) | time Q1-Q3 (ms) | "
      "length median (m) | length Q1-Q3 (m) | shortest (m) |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  for (const PlannerSummary& s : summaries) {
    const bool any = !s.lengths_m.empty();
    md += "| " + s.planner + " | " + (s.ompl ? "OMPL" : "cosim") + " | " +
          std::to_string(s.solved) + "/" + std::to_string(s.runs) + " | " +
          fixed(100.0 * s.solved / s.runs, 0) + " | " + fixed(quantile(s.times_ms, 0.5), 1) +
          " | " + fixed(quantile(s.times_ms, 0.25), 1) + "-" +
          fixed(quantile(s.times_ms, 0.75), 1) + " | " +
          (any ? fixed(quantile(s.lengths_m, 0.5), 2) : "-") + " | " +
          (any ? fixed(quantile(s.lengths_m, 0.25), 2) + "-" + fixed(quantile(s.lengths_m, 0.75), 2)
               : "-") +
          " | " + (any ? fixed(quantile(s.lengths_m, 0.0), 2) : "-") + " |\n";
  }
  return md;
}

}  // namespace cosim
