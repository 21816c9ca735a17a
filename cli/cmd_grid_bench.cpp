// cosim grid-bench MAP.map SCEN.scen --planner NAME: the single-agent MovingAI benchmark. Plans
// every scenario line (or the first N) with any grid planner of the registry, writes one CSV row
// per line and prints a summary. Exit 0: all solved (and, for optimal planners under the
// MovingAI rules, every length equal to the published optimum); 1: some line failed; 2: bad
// input.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli/command.h"
#include "cli/interrupt_flag.h"
#include "cli/option_checks.h"
#include "cli/set_options.h"
#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "core/stop_request.h"
#include "planning/grid/movingai.h"
#include "planning/planner_registry.h"

namespace cosim::cli {

namespace {

// The published optimum is the octile length without corner cutting; a planner is held to it
// only if it promises optimal paths under exactly those rules.
bool heldToOptimum(const std::string& planner, const ParamSet& params) {
  if (planner != "astar" && planner != "dijkstra" && planner != "bellman_ford") return false;
  const auto& p = params.effective();
  auto value = [&](const char* key, const char* fallback) {
    auto it = p.find(key);
    return it == p.end() ? std::string(fallback) : it->second;
  };
  const std::string connectivity = value("connectivity", "0");
  return (connectivity == "0" || connectivity == "8") &&
         value("corner_cutting", "false") == "false" &&
         std::stod(value("heuristic_weight", "1")) == 1.0;
}

std::string number(double v, const char* format = "%.6f") {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

struct GridBenchArgs {
  std::string map, scen, planner, out;
  int limit = 0;
  double time_limit = 10.0;
  std::vector<std::string> sets;
};

// Every scenario line must be for this map (by name and size).
void checkScenarioMatchesMap(const std::vector<MovingAIScenarioLine>& lines,
                             const OccupancyGrid& grid, const std::string& scen,
                             const std::string& map_name) {
  for (const auto& s : lines) {
    const std::string place = "line " + std::to_string(s.line);
    if (s.width != grid.nx() || s.height != grid.ny())
      throw InputError(scen, place,
                       "scenario is for a " + std::to_string(s.width) + "x" +
                           std::to_string(s.height) + " map, but " + map_name + " is " +
                           std::to_string(grid.nx()) + "x" + std::to_string(grid.ny()));
    if (std::filesystem::path(s.map).filename().string() != map_name)
      throw InputError(scen, place, "scenario names map '" + s.map + "', not '" + map_name + "'");
  }
}

// The counts the summary reports.
struct GridBenchTally {
  std::size_t solved = 0, mismatches = 0;
  double total_us = 0.0;
};

// Plans one scenario line (query seed i + 1) and appends its CSV row.
void planLine(GridPlanner& planner, const OccupancyGrid& grid, const MovingAIScenarioLine& s,
              std::size_t i, double time_limit, std::string& csv, GridBenchTally& tally) {
  GridQuery q;
  q.grid = &grid;
  q.start = {s.start_x, s.start_y, 0};
  q.goal = {s.goal_x, s.goal_y, 0};
  q.time_limit_s = time_limit;
  q.seed = i + 1;
  const GridPlanResult r = planner.solveGrid(q, StopToken::untimed());
  const double us = r.time_ms * 1000.0;
  tally.total_us += us;
  const auto exp = r.counters.find("expansions");
  csv += std::to_string(i) + "," + std::to_string(s.start_x) + "," + std::to_string(s.start_y) +
         "," + std::to_string(s.goal_x) + "," + std::to_string(s.goal_y) + "," +
         number(s.optimal_length, "%.8f") + ",";
  if (r.success) {
    ++tally.solved;
    const double diff = r.length - s.optimal_length;
    if (!matchesOptimalLength(s, r.length)) ++tally.mismatches;
    csv += number(r.length, "%.8f") + "," + number(us, "%.1f") + "," +
           (exp != r.counters.end() ? number(exp->second, "%.0f") : "") + "," +
           number(diff, "%.8f") + ",\n";
  } else {
    csv += "," + number(us, "%.1f") + "," +
           (exp != r.counters.end() ? number(exp->second, "%.0f") : "") + ",," +
           csvField(r.message) + "\n";
  }
}

void runGridBench(const GridBenchArgs& a, CommandContext& ctx) {
  installInterruptFlag();
  // The output is checked before any planning (a file there must be one cosim wrote,
  // core/output_manifest.h), and, once the inputs passed their checks, an older one at that path
  // goes: an interrupted rerun must not leave it looking like this run's.
  if (!a.out.empty()) checkOutputPath(a.out, "--out");
  ParamSet params("command line");
  applySetOptions(a.sets, params);
  auto planner = makeGridPlanner(a.planner, params);
  const bool optimal = heldToOptimum(a.planner, params);

  const OccupancyGrid grid = readMovingAIMap(a.map);
  auto lines = readMovingAIScenario(a.scen);
  const std::string map_name = std::filesystem::path(a.map).filename().string();
  checkScenarioMatchesMap(lines, grid, a.scen, map_name);
  if (!a.out.empty()) {
    const std::filesystem::path out = a.out;
    removeStaleResults(out.has_parent_path() ? out.parent_path() : ".", {out.filename().string()});
  }
  if (a.limit > 0 && static_cast<std::size_t>(a.limit) < lines.size()) lines.resize(a.limit);

  std::string csv =
      "id,start_x,start_y,goal_x,goal_y,optimal,length,time_us,expansions,difference,message\n";
  GridBenchTally tally;
  for (std::size_t i = 0; i < lines.size() && !stopRequested(); ++i)
    planLine(*planner, grid, lines[i], i, a.time_limit, csv, tally);
  if (stopRequested()) {  // the lines planned after the stop failed at once: no result
    std::cerr << "cosim: interrupted"
              << (a.out.empty() ? std::string() : "; " + a.out + " was not written") << "\n";
    ctx.status = 1;
    return;
  }
  if (!a.out.empty()) {
    writeFileAtomically(a.out, csv);
    writeOutputManifestOf(a.out, "grid-bench");  // proves the file cosim's to a later bench
  }

  const std::size_t solved = tally.solved, mismatches = tally.mismatches;
  const double mean_us = lines.empty() ? 0.0 : tally.total_us / lines.size();
  std::cout << "grid-bench " << a.planner << " on " << map_name << "\n"
            << "  lines:      " << lines.size() << "\n"
            << "  solved:     " << solved << "\n"
            << "  mismatches: " << mismatches
            << " (|length - optimal| > 1e-4 relative or the file's rounding"
            << (optimal ? ")" : "; not held to the optimum)") << "\n"
            << "  mean time:  " << number(mean_us, "%.1f") << " us\n";
  if (!a.out.empty()) std::cout << "  written:    " << a.out << "\n";
  ctx.status = (solved < lines.size() || (optimal && mismatches > 0)) ? 1 : 0;
}

}  // namespace

void addGridBenchCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand(
      "grid-bench",
      "Single-agent MovingAI benchmark: plans every line of SCEN.scen on MAP.map with a grid\n"
      "planner and compares with the published optimal lengths (8-connected, no corner cutting).\n"
      "CSV columns: id,start_x,start_y,goal_x,goal_y,optimal,length,time_us,expansions,\n"
      "difference,message. Exit 1 if a line has no path (or an optimal planner misses the\n"
      "optimum), 2 on bad input.");
  auto a = std::make_shared<GridBenchArgs>();
  cmd->add_option("map", a->map, "MovingAI .map file")->required();
  cmd->add_option("scen", a->scen, "MovingAI .scen file for that map")->required();
  cmd->add_option("--planner", a->planner, "grid planner name (see cosim plan --list)")->required();
  cmd->add_option("--limit", a->limit, "plan only the first N lines (0 = all)")
      ->check(wholeNumberIn(0, 100000000));
  cmd->add_option("--out", a->out, "write the per-line CSV here");
  cmd->add_option("--time-limit", a->time_limit, "seconds per line (default 10)")
      ->check(numberIn(0.001, 3600.0));
  cmd->add_option("--set", a->sets, "planner parameter, e.g. --set connectivity=4 (repeatable)");
  cmd->callback([a, &ctx] { runGridBench(*a, ctx); });
}

}  // namespace cosim::cli
