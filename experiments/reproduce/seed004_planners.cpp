// cosim reproduce seed004-planners: seed 004's planned comparison (§6.1-6.3, TODO notes only):
// LRA* vs CA* vs WHCA* (plus HCA*, the potential field, independent A* and CBS as the optimal
// reference) "under the same initial conditions", on a maze, an open room and a bottleneck,
// measuring success, path lengths and time against the number of robots. The thesis reports no
// numbers, so the seed column holds its qualitative claims.
#include <cmath>
#include <string>
#include <vector>

#include "experiments/reproduce/mapf_trial.h"
#include "experiments/reproduce/reproduction.h"
#include "experiments/reproduce/seed004_environments.h"

namespace cosim::reproduce {

namespace {

struct PlannerSetting {
  const char* label;
  const char* planner;
  std::vector<std::pair<std::string, std::string>> params;
};

const char* seedClaim(Seed004Environment env, const std::string& planner) {
  if (planner == "potential_field") return "fails (local minima, §4.6)";
  if (planner == "lra_star")
    return env == Seed004Environment::kOpen ? "may be enough in open space (§1.1)"
                                            : "cycles in bottlenecks (§3.2.1)";
  if (planner == "whca_star") return "most promising (§3.6)";
  if (planner == "ca_star") return "better than LRA* (§3.6)";
  return "";
}

}  // namespace

Report seed004Planners(const Options& options) {
  const int runs = options.runs > 0 ? options.runs : (options.quick ? 2 : 20);
  const int size = 15;  // the seed's software tests: 15 x 15 maps, 20 simulations
  const std::vector<int> robot_counts =
      options.quick ? std::vector<int>{2, 5} : std::vector<int>{2, 5, 10, 20};
  // The same limit in --quick runs: a shorter one made their CBS results depend on the machine's
  // speed (one 5-robot maze instance needs about a second under AddressSanitizer).
  const double time_limit_s = 5.0;
  const std::vector<PlannerSetting> planners = {
      {"independent A*", "independent_astar", {}},
      {"LRA*", "lra_star", {}},
      {"CA*", "ca_star", {}},
      {"HCA*", "hca_star", {}},
      {"WHCA* (w=8, dynamic)", "whca_star", {}},
      {"potential field", "potential_field", {}},
      {"CBS (optimal)", "cbs", {}},
  };

  std::string md =
      "# Seed 004: LRA* vs CA* vs WHCA* from the same starts\n\n"
      "Seed 004 (Szulc 2018) publishes **no numeric results**: its chapter 6 is TODO notes and its "
      "list of tables is empty. Its planned comparison is run here; the last column quotes the "
      "seed's qualitative claim where it makes one.\n\n"
      "Set-up: " +
      std::to_string(size) + " x " + std::to_string(size) +
      " maps (the size of the seed software's effectiveness tests), 4-connected; maze = the "
      "seed's generator (§4.1), open = no obstacles, bottleneck = two rooms joined by one door; "
      "random distinct starts and goals; " +
      std::to_string(runs) + " instances per row (seed " + std::to_string(options.seed) +
      " + i), the same instances for every planner; time limit " + formatFixed(time_limit_s, 0) +
      " s per run. A run counts as solved only if the independent validator accepts its paths. "
      "SOC = sum of arrival times; SOC/CBS is over the instances solved by both.\n\n"
      "| environment | robots | planner | success % | mean SOC | SOC / CBS | mean time ms | seed "
      "004 says |\n|---|---|---|---|---|---|---|---|\n";
  std::vector<JsonObject> rows;
  for (const auto env :
       {Seed004Environment::kMaze, Seed004Environment::kOpen, Seed004Environment::kBottleneck})
    for (const int robots : robot_counts) {
      std::vector<MapfTrialSummary> summary(planners.size());
      std::vector<double> ratio_sum(planners.size(), 0.0);
      std::vector<int> ratio_n(planners.size(), 0);
      for (int i = 0; i < runs; ++i) {
        const std::uint64_t seed = options.seed + static_cast<std::uint64_t>(i);
        const MapfInstance inst =
            randomlyPlacedRobots(seed004Map(env, size, size, seed), robots, seed * 7919 + robots);
        std::vector<MapfTrial> trials;
        for (const auto& p : planners)
          trials.push_back(runMapfTrial(p.planner, p.params, inst, time_limit_s, seed));
        const MapfTrial& cbs = trials.back();
        for (std::size_t k = 0; k < planners.size(); ++k) {
          summary[k].add(trials[k]);
          if (trials[k].solved && cbs.solved && cbs.sum_of_costs > 0) {
            ratio_sum[k] += static_cast<double>(trials[k].sum_of_costs) / cbs.sum_of_costs;
            ++ratio_n[k];
          }
        }
      }
      for (std::size_t k = 0; k < planners.size(); ++k) {
        const auto& s = summary[k];
        md += std::string("| ") + seed004EnvironmentName(env) + " | " + std::to_string(robots) +
              " | " + planners[k].label + " | " + formatFixed(s.successPercent(), 0) + " | " +
              formatFixed(s.solved ? s.meanSumOfCosts() : NAN, 1) + " | " +
              formatFixed(ratio_n[k] ? ratio_sum[k] / ratio_n[k] : NAN, 3) + " | " +
              formatFixed(s.meanTimeMs(), 2) + " | " + seedClaim(env, planners[k].planner) + " |\n";
        JsonObject row;
        row.add("environment", seed004EnvironmentName(env))
            .add("robots", robots)
            .add("planner", planners[k].planner)
            .add("instances", s.runs)
            .add("success_percent", s.successPercent())
            .add("mean_sum_of_costs", s.solved ? s.meanSumOfCosts() : NAN)
            .add("soc_over_cbs", ratio_n[k] ? ratio_sum[k] / ratio_n[k] : NAN)
            .add("mean_time_ms", s.meanTimeMs())
            .add("seed_claim", seedClaim(env, planners[k].planner));
        rows.push_back(row);
      }
    }
  return {md, rows};
}

}  // namespace cosim::reproduce
