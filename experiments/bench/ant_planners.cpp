#include "experiments/bench/ant_planners.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "experiments/bench/thread_cpu_clock.h"
#include "planning/grid/astar.h"
#include "planning/grid/movingai.h"
#include "planning/planner_registry.h"

namespace cosim::bench {
namespace {

// One row of the table: a registry name with parameter settings. Other ant families add rows.
struct Variant {
  std::string label;
  std::string planner;
  std::vector<std::pair<std::string, std::string>> params;
};

const std::vector<Variant>& variants() {
  static const std::vector<Variant> list = {
      {"msac", "msac", {}},                          // m 4, MAX 3 (seed defaults)
      {"msac_max1", "msac", {{"iterations", "1"}}},  // one iteration: the fast setting
      // + the wider-range smoothing the seed's author proposes (range 64 path nodes)
      {"msac_max1_wide", "msac", {{"iterations", "1"}, {"smoothing_range", "64"}}},
      {"sacodm", "sacodm", {}},  // beta 1, rolling gamma 1, EAS 1
      {"saco", "saco", {}},      // beta 0, gamma 0, Ant System
      {"sacodm_wide", "sacodm", {{"smoothing_range", "64"}}},
      {"mmas", "mmas", {}},  // seed 002 baseline: 10 ants, staircase LS
      {"mmas_no_ls", "mmas", {{"local_search", "false"}}},
      {"mmas_fast", "mmas", {{"ants", "5"}, {"stall_iterations", "1"}}},
      {"ant_grid", "ant_grid", {}},  // seed 002 part A defaults
      {"ant_grid_ls", "ant_grid", {{"local_search", "true"}}},
      {"ga", "ga", {}},    // seed 002's comparison GA
      {"pso", "pso", {}},  // Mohemmed et al. 2008 priority PSO
  };
  return list;
}

struct MapSet {
  std::string map, scen;
  int queries;  // spread evenly over the scenario file
};

std::vector<MapSet> mapSets(bool quick) {
  const std::string bundled = COSIM_SOURCE_DIR "/experiments/maps/";
  std::vector<MapSet> sets = {{bundled + "random-32-32-10.map",
                               bundled + "random-32-32-10-random-1.scen", quick ? 10 : 100}};
  if (quick) return sets;
  // The MovingAI maps kept in the repository: two game maps and a city map.
  const std::string test_maps = COSIM_SOURCE_DIR "/tests/data/movingai/";
  sets.push_back({test_maps + "arena.map", test_maps + "arena.map.scen", 60});
  sets.push_back({bundled + "den312d.map", bundled + "den312d-random-1.scen", 40});
  sets.push_back({test_maps + "Berlin_0_256.map", test_maps + "Berlin_0_256.map.scen", 10});
  return sets;
}

struct Totals {
  int queries = 0, solved = 0;
  double gap_sum = 0.0, ms = 0.0, astar_ms = 0.0;
};

}  // namespace

Section benchAntPlanners(bool quick) {
  Section section;
  section.name = "ant_planners_vs_astar";
  const double time_limit_s = quick ? 2.0 : 10.0;
  std::vector<Totals> totals(variants().size());
  for (const MapSet& set : mapSets(quick)) {
    const OccupancyGrid grid = readMovingAIMap(set.map);
    const auto scen = readMovingAIScenario(set.scen);
    const std::size_t stride = std::max<std::size_t>(1, scen.size() / set.queries);
    for (std::size_t i = 0, n = 0; i < scen.size() && static_cast<int>(n) < set.queries;
         i += stride, ++n) {
      const Cell s{scen[i].start_x, scen[i].start_y, 0}, t{scen[i].goal_x, scen[i].goal_y, 0};
      double t0 = threadCpuMs();
      const GridPlanResult best = planAStar(grid, s, t);
      const double astar_ms = threadCpuMs() - t0;
      if (!best.success) continue;
      for (std::size_t v = 0; v < variants().size(); ++v) {
        ParamSet params("bench");
        for (const auto& [k, value] : variants()[v].params) params.set(k, value);
        auto planner = makeGridPlanner(variants()[v].planner, params);
        GridQuery q;
        q.grid = &grid;
        q.start = s;
        q.goal = t;
        q.seed = i + 1;
        q.time_limit_s = time_limit_s;
        t0 = threadCpuMs();
        const GridPlanResult r = planner->solveGrid(q, StopToken::untimed());
        Totals& tot = totals[v];
        tot.ms += threadCpuMs() - t0;
        tot.astar_ms += astar_ms;
        ++tot.queries;
        if (!r.success) continue;
        ++tot.solved;
        tot.gap_sum += r.length / best.length - 1.0;
      }
    }
  }
  std::string best_label;
  double best_gap = 1e300, best_ratio = 0.0;
  for (std::size_t v = 0; v < variants().size(); ++v) {
    const Totals& t = totals[v];
    const std::string& label = variants()[v].label;
    const double gap = t.solved ? 100.0 * t.gap_sum / t.solved : std::nan("");
    const double ratio = t.astar_ms > 0 ? t.ms / t.astar_ms : std::nan("");
    section.figures.push_back({label + "_mean_gap", gap, "%"});
    section.figures.push_back(
        {label + "_time_per_query", t.queries ? t.ms / t.queries : 0.0, "ms"});
    section.figures.push_back({label + "_time_vs_astar", ratio, "x"});
    section.figures.push_back(
        {label + "_solved", t.queries ? 100.0 * t.solved / t.queries : 0.0, "%"});
    // The best variant: the smallest gap among those that solve every query within the time
    // budget (10x A*); if none is within it, the smallest gap of all.
    const bool within = t.solved == t.queries && ratio <= 10.0;
    const bool best_within = best_ratio <= 10.0 && !best_label.empty();
    if (t.solved == t.queries && ((within && (!best_within || gap < best_gap)) ||
                                  (!within && !best_within && gap < best_gap))) {
      best_gap = gap;
      best_ratio = ratio;
      best_label = label;
    }
  }
  const Totals& any = totals.front();
  section.figures.push_back(
      {"astar_time_per_query", any.queries ? any.astar_ms / any.queries : 0.0, "ms"});
  const bool met = best_gap < 2.0 && best_ratio <= 10.0;
  section.note =
      "ant planners vs optimal A* on " + std::to_string(any.queries) +
      " MovingAI queries (no corner cutting); best within 10x A*'s time (else overall): " +
      best_label + " with gap " + std::to_string(best_gap).substr(0, 5) + "% at " +
      std::to_string(best_ratio).substr(0, 6) +
      "x A*'s time; target gap < 2% at <= 10x: " + (met ? "met" : "not met");
  return section;
}

}  // namespace cosim::bench
