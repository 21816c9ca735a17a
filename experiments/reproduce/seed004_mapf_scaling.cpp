// cosim reproduce seed004-mapf-scaling: success rate and sum of costs of WHCA* (seed 004's
// favourite, §3.6) and CBS (the optimal reference; Sharon et al. 2015) against the number of
// agents, on the MovingAI MAPF benchmark maps (Stern et al., SoCS 2019), 4-connected, the first
// N agents of each -random-k and -even-k scenario file. Seed 004 has no numbers to set beside.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "experiments/reproduce/mapf_trial.h"
#include "experiments/reproduce/reproduction.h"
#include "planning/grid/movingai.h"
#include "planning/mapf/movingai_instance.h"

namespace cosim::reproduce {

namespace {

// The benchmark folder: the shared data set if present, else the few files bundled for tests.
std::filesystem::path mapfDataDir(bool quick) {
  const std::filesystem::path shared = "/work/shared/data/mapf";
  if (!quick && std::filesystem::exists(shared / "random-32-32-10.map")) return shared;
  return std::filesystem::path(COSIM_SOURCE_DIR) / "tests/data/mapf";
}

}  // namespace

Report seed004MapfScaling(const Options& options) {
  const std::filesystem::path dir = mapfDataDir(options.quick);
  const std::vector<std::string> maps = {
      "empty-8-8",    "empty-16-16", "empty-32-32",           "random-32-32-10",
      "maze-32-32-2", "den312d",     "warehouse-10-20-10-2-1"};
  const std::vector<int> agent_counts =
      options.quick ? std::vector<int>{2, 5} : std::vector<int>{10, 20, 50, 100};
  std::vector<std::string> scens;
  const int per_kind = options.runs > 0 ? options.runs : (options.quick ? 1 : 5);
  for (const char* kind : {"random", "even"})
    for (int k = 1; k <= std::min(per_kind, 5); ++k)
      scens.push_back(std::string("-") + kind + "-" + std::to_string(k) + ".scen");
  const double whca_limit_s = options.quick ? 1.0 : 10.0, cbs_limit_s = options.quick ? 1.0 : 5.0;

  std::string md =
      "# WHCA* and CBS against the number of agents on the MAPF benchmarks\n\n"
      "Seed 004 publishes **no numeric results**; it expects WHCA* to be the most effective of its "
      "methods (§3.6) and its own WHCA* to solve bottlenecks only for few agents (§4.4). CBS is "
      "the optimal reference. Data: " +
      dir.string() +
      " (MovingAI MAPF benchmarks, Stern et al. 2019), 4-connected, instance = the first N lines "
      "of each scenario file (" +
      std::to_string(scens.size()) +
      " files per map where present: -random-k and -even-k). WHCA*: window 8, dynamic "
      "priorities, replanning every 4 steps, time limit " +
      formatFixed(whca_limit_s, 0) +
      " s; CBS: bypassing, conflict-avoidance tie-breaking, time "
      "limit " +
      formatFixed(cbs_limit_s, 0) +
      " s. Solved = accepted by the independent validator. SOC = sum of arrival times; "
      "\"SOC both\" compares the two on the instances both solved (WHCA* / CBS).\n\n"
      "| map | agents | instances | WHCA* success % | WHCA* mean SOC | WHCA* mean ms | CBS "
      "success % | CBS mean SOC | CBS mean ms | SOC both (WHCA*/CBS) |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n";
  std::vector<JsonObject> rows;
  for (const auto& map : maps) {
    const auto map_path = dir / (map + ".map");
    if (!std::filesystem::exists(map_path)) continue;
    for (const int n : agent_counts) {
      MapfTrialSummary whca, cbs;
      double both_whca = 0, both_cbs = 0;
      for (const auto& suffix : scens) {
        const auto scen_path = dir / (map + suffix);
        if (!std::filesystem::exists(scen_path)) continue;
        // "Where the map allows": a scenario has as many agents as it has lines.
        if (static_cast<int>(readMovingAIScenario(scen_path.string()).size()) < n) continue;
        const MapfInstance inst =
            readMovingAIMapfInstance(map_path.string(), scen_path.string(), n);
        const MapfTrial w = runMapfTrial("whca_star", {}, inst, whca_limit_s, options.seed);
        const MapfTrial c = runMapfTrial("cbs", {}, inst, cbs_limit_s, options.seed);
        whca.add(w);
        cbs.add(c);
        if (w.solved && c.solved) both_whca += w.sum_of_costs, both_cbs += c.sum_of_costs;
      }
      if (whca.runs == 0) continue;
      md += "| " + map + " | " + std::to_string(n) + " | " + std::to_string(whca.runs) + " | " +
            formatFixed(whca.successPercent(), 0) + " | " +
            formatFixed(whca.solved ? whca.meanSumOfCosts() : NAN, 1) + " | " +
            formatFixed(whca.meanTimeMs(), 1) + " | " + formatFixed(cbs.successPercent(), 0) +
            " | " + formatFixed(cbs.solved ? cbs.meanSumOfCosts() : NAN, 1) + " | " +
            formatFixed(cbs.meanTimeMs(), 1) + " | " +
            formatFixed(both_cbs > 0 ? both_whca / both_cbs : NAN, 3) + " |\n";
      for (const auto& [planner, t] :
           {std::pair<const char*, const MapfTrialSummary*>{"whca_star", &whca}, {"cbs", &cbs}}) {
        JsonObject row;
        row.add("map", map)
            .add("agents", n)
            .add("planner", planner)
            .add("instances", t->runs)
            .add("success_percent", t->successPercent())
            .add("mean_sum_of_costs", t->solved ? t->meanSumOfCosts() : NAN)
            .add("mean_time_ms", t->meanTimeMs());
        rows.push_back(row);
      }
    }
  }
  return {md, rows};
}

}  // namespace cosim::reproduce
