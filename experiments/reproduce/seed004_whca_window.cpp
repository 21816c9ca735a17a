// cosim reproduce seed004-whca-window: seed 004's planned WHCA* studies (§6.3, TODO notes only):
// "WHCA* with different time windows" and "priority assignment and priority change: how the
// success rate changes once priority changes are introduced", on the maze, the open room and the
// bottleneck. The thesis reports no numbers; its claims (§3.5, §4.4-4.5) are quoted beside ours.
#include <cmath>
#include <string>
#include <vector>

#include "experiments/reproduce/mapf_trial.h"
#include "experiments/reproduce/reproduction.h"
#include "experiments/reproduce/seed004_environments.h"

namespace cosim::reproduce {

Report seed004WhcaWindow(const Options& options) {
  const int runs = options.runs > 0 ? options.runs : (options.quick ? 2 : 20);
  const int size = 15;
  const std::vector<int> robot_counts =
      options.quick ? std::vector<int>{5} : std::vector<int>{2, 5, 10, 20};
  const std::vector<int> windows =
      options.quick ? std::vector<int>{4, 8} : std::vector<int>{2, 4, 8, 16, 32};
  const double time_limit_s = options.quick ? 1.0 : 5.0;

  std::string md =
      "# Seed 004: WHCA* over window sizes, fixed vs dynamic priorities\n\n"
      "Seed 004 publishes **no numeric results** (chapter 6 is TODO notes). Its claims: the window "
      "should be about the number of agents or the longest expected jam (§3.5); its own WHCA* "
      "\"solves the bottleneck, but only for a small number of agents (2)\" (§4.4); raising the "
      "priority of an agent that found no route and retrying should help (§4.5).\n\n"
      "Set-up: " +
      std::to_string(size) + " x " + std::to_string(size) +
      " maps (maze = the seed's generator, open, bottleneck = one door), 4-connected, random "
      "distinct starts and goals, " +
      std::to_string(runs) +
      " instances per cell (the same for every column), replanning every w/2 steps, at most "
      "width x height steps (the seed software's limit), time limit " +
      formatFixed(time_limit_s, 0) +
      " s. Cells: success % (mean sum of costs of the solved runs).\n\n| environment | robots | "
      "priorities |";
  for (const int w : windows) md += " w=" + std::to_string(w) + " |";
  md += "\n|---|---|---|";
  for (std::size_t i = 0; i < windows.size(); ++i) md += "---|";
  md += "\n";
  std::vector<JsonObject> rows;
  for (const auto env :
       {Seed004Environment::kMaze, Seed004Environment::kOpen, Seed004Environment::kBottleneck})
    for (const int robots : robot_counts) {
      std::vector<MapfInstance> instances;
      for (int i = 0; i < runs; ++i) {
        const std::uint64_t seed = options.seed + static_cast<std::uint64_t>(i);
        instances.push_back(
            randomlyPlacedRobots(seed004Map(env, size, size, seed), robots, seed * 7919 + robots));
      }
      for (const char* priorities : {"fixed", "dynamic"}) {
        md += std::string("| ") + seed004EnvironmentName(env) + " | " + std::to_string(robots) +
              " | " + priorities + " |";
        for (const int w : windows) {
          MapfTrialSummary s;
          for (int i = 0; i < runs; ++i)
            s.add(runMapfTrial("whca_star",
                               {{"window", std::to_string(w)}, {"priorities", priorities}},
                               instances[i], time_limit_s, options.seed + i));
          // append(): GCC 12 warns falsely (-Wrestrict) on " " + std::string.
          md.append(" ")
              .append(formatFixed(s.successPercent(), 0))
              .append(" (")
              .append(formatFixed(s.solved ? s.meanSumOfCosts() : NAN, 1))
              .append(") |");
          JsonObject row;
          row.add("environment", seed004EnvironmentName(env))
              .add("robots", robots)
              .add("priorities", priorities)
              .add("window", w)
              .add("instances", s.runs)
              .add("success_percent", s.successPercent())
              .add("mean_sum_of_costs", s.solved ? s.meanSumOfCosts() : NAN);
          rows.push_back(row);
        }
        md += "\n";
      }
    }
  return {md, rows};
}

}  // namespace cosim::reproduce
