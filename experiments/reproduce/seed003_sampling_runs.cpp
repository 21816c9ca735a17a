#include "experiments/reproduce/seed003_sampling_runs.h"

#include "planning/planner_registry.h"

namespace cosim::reproduce {

std::vector<SamplingColumn> samplingColumnsOf(const Seed003SamplingTable& t) {
  std::vector<SamplingColumn> c = {
      {"RRT", "rrt", "rrt", false, 0, 0},
      {"RRT* (thesis, Fig. 16)", "rrt_star_thesis", "rrt_star_thesis", true, 0, 1},
      {"RRT* (Karaman-Frazzoli)", "rrt_star", "rrt_star", false, 0, -1}};
  for (int k = 0; k < 4; ++k)
    c.push_back({"RRT*FN " + std::to_string(t.caps[k]) + " (thesis)",
                 "rrt_star_fn_" + std::to_string(t.caps[k]), "rrt_star_thesis", true, t.caps[k],
                 2 + k});
  return c;
}

Samples runSamplingColumn(const Seed003SamplingTable& t, const Seed003Map& map,
                          const SamplingColumn& col, const Options& options, int runs,
                          const RunVariant& variant) {
  Samples s;
  for (int i = 0; i < runs; ++i) {
    ParamSet p("seed003-sampling");
    p.set("mode", std::to_string(t.mode));
    p.set("max_nodes", std::to_string(t.max_nodes));
    p.set("step", std::to_string(t.step));
    // The thesis's settings for every column (rrt_star_thesis has them as defaults).
    p.set("goal_bias", "0");
    p.set("goal_tolerance",
          std::to_string(variant.goal_tolerance < 0 ? t.step : variant.goal_tolerance));
    if (variant.linear_scan) p.set("neighbour_search", "linear");
    if (col.planner != "rrt") p.set("rewire_radius", std::to_string(t.radius));
    if (col.cap > 0) p.set("max_tree_nodes", std::to_string(col.cap));
    for (const auto& [key, value] : variant.params) p.set(key, value);
    auto solver = makePlanner(col.planner, p, "seed003-sampling");
    PlanningProblem prob;
    prob.world = &map.world;
    prob.start = map.start;
    prob.goal = map.goal;
    prob.inflation = 0.0;  // the thesis planned for a point mass
    prob.planar = map.planar;
    prob.time_limit_s = 60.0;
    prob.seed = options.seed + static_cast<std::uint64_t>(i);
    const PlanResult r = solver->solve(prob, StopToken::untimed());
    ++s.runs;
    s.times_ms.push_back(r.time_ms);
    auto counter = [&](const char* k) { return r.counters.count(k) ? r.counters.at(k) : 0.0; };
    s.nodes.push_back(counter("nodes"));
    if (col.cap > 0) s.removed.push_back(counter("removed_nodes"));
    if (r.success) {
      ++s.successes;
      s.lengths.push_back(r.path.length());
      if (r.counters.count("goal_cost")) s.goal_costs.push_back(r.counters.at("goal_cost"));
      if (s.best.empty() || r.path.length() < s.best.length()) s.best = r.path;
      // RRT reports no first-path count: in mode 1 it stops at its first path, so that is its
      // node count; in mode 2 it is not known (left out, not the total).
      if (r.counters.count("first_path_nodes"))
        s.first_path_nodes.push_back(r.counters.at("first_path_nodes"));
      else if (t.mode == 1)
        s.first_path_nodes.push_back(counter("nodes"));
    }
  }
  return s;
}

}  // namespace cosim::reproduce
