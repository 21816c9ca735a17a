#include "experiments/reproduce/seed003_sampling_checks.h"

#include <sstream>
#include <tuple>

#include "experiments/reproduce/report_files.h"
#include "experiments/reproduce/run_spread.h"
#include "experiments/reproduce/seed003_sampling_runs.h"

namespace cosim::reproduce {

namespace {

const Seed003SamplingTable* tableLabelled(const char* label) {
  for (const Seed003SamplingTable& t : kSeed003SamplingTables)
    if (std::string(t.label) == label) return &t;
  return nullptr;
}

const Seed003Map* mapCalled(const std::vector<Seed003Map>& maps, const std::string& name) {
  for (const auto& m : maps)
    if (m.name == name) return &m;
  return nullptr;
}

}  // namespace

std::string smallCapSection(const Options& options, int runs, const std::vector<Seed003Map>& maps,
                            SamplingChecks& checks, std::vector<JsonObject>& rows) {
  std::ostringstream md;
  md << "\n## Caps below N/5\n\nThe thesis: RRT*FN runs with a cap below N/5 \"failed in more "
        "than 90 % of cases\" and are not tabulated (sec. 4.1.2, 2D). The thesis's RRT*FN on the "
        "2D map with caps N/10 and N/7:\n\n| table | cap | success |\n|---|---|---|\n";
  for (const char* label : {"Tab. 4", "Tab. 5"}) {
    const Seed003SamplingTable* t = tableLabelled(label);
    const Seed003Map* map = t ? mapCalled(maps, t->map) : nullptr;
    if (!map) continue;
    for (const int cap : {t->max_nodes / 10, t->max_nodes / 7}) {
      const SamplingColumn col{"RRT*FN " + std::to_string(cap),
                               "rrt_star_fn_" + std::to_string(cap),
                               "rrt_star_thesis",
                               true,
                               cap,
                               -1};
      const Samples s = runSamplingColumn(*t, *map, col, options, runs);
      checks.small_caps.push_back({t, cap, s.runs, s.successes});
      md << "| " << label << " (mode " << t->mode << ") | " << cap << " | " << s.successes << "/"
         << s.runs << " |\n";
      JsonObject row;
      row.add("table", label)
          .add("map", "2d")
          .add("planner", col.json_name)
          .add("check", "cap_below_n_over_5")
          .add("runs", s.runs)
          .add("successes", s.successes);
      rows.push_back(row);
    }
  }
  return md.str();
}

std::string modeTwoSection(const Options& options, int runs, const std::vector<Seed003Map>& maps,
                           SamplingChecks& checks, std::vector<JsonObject>& rows) {
  const Seed003SamplingTable *m1 = tableLabelled("Tab. 4"), *m2 = tableLabelled("Tab. 5");
  const Seed003Map* map = m1 ? mapCalled(maps, m1->map) : nullptr;
  if (!map || !m2) return "";
  std::ostringstream md;
  md << "\n## Mode 2: the thesis's two candidate causes, tested\n\nThe thesis's mode 2 leaves "
        "the 2D path essentially unchanged (RRT* "
     << fixed(m1->length[1], 2) << " -> " << fixed(m2->length[1], 2) << " m, "
     << fmt("%.1f %%", 100 * m2->length[1] / m1->length[1])
     << "). Two ways its RRT* could stop shortening after the first path, each switched on in "
        "our thesis RRT* (planner `rrt_star_thesis`): `rewire_costs: node` (a rewired node's "
        "new cost is not passed on to its descendants, as in a MATLAB tree kept as parent and "
        "cost arrays without a pass over the subtree; their stale costs then steer choose-parent, "
        "rewiring and the goal) and `goal_reattach: false` (the goal stays on the node that "
        "first reached it, neither re-attached by the goal test nor rewired). Lengths are of the "
        "path "
        "the tree finally holds; the goal's cost is its cost-to-come as the tree stores it, which "
        "a program reporting that value instead of measuring the path would print:\n\n"
        "| rules | mode 1 length [m] | mode 2 length [m] | mode 2 / mode 1 | mode 1 goal cost [m] "
        "| mode 2 goal cost [m] | mode 2 / mode 1 |\n|---|---|---|---|---|---|---|\n";
  const SamplingColumn star = samplingColumnsOf(*m1)[1];
  for (const auto& [name, propagate, reattach] :
       {std::tuple<const char*, bool, bool>{"usual (both as RRT*)", true, true},
        {"rewire_costs: node", false, true},
        {"goal_reattach: false", true, false},
        {"both", false, false}}) {
    const RunVariant v{-1.0,
                       false,
                       {{"rewire_costs", propagate ? "subtree" : "node"},
                        {"goal_reattach", reattach ? "true" : "false"}}};
    const Samples s1 = runSamplingColumn(*m1, *map, star, options, runs, v);
    const Samples s2 = runSamplingColumn(*m2, *map, star, options, runs, v);
    ModeTwoOutcome o{name,
                     propagate,
                     reattach,
                     spreadOf(s1.lengths).mean,
                     spreadOf(s2.lengths).mean,
                     spreadOf(s1.goal_costs).mean,
                     spreadOf(s2.goal_costs).mean};
    md << "| " << name << " | " << fixed(o.mode1_length, 2) << " | " << fixed(o.mode2_length, 2)
       << " | " << fmt("%.1f %%", 100 * o.ratio()) << " | " << fixed(o.mode1_cost, 2) << " | "
       << fixed(o.mode2_cost, 2) << " | " << fmt("%.1f %%", 100 * o.costRatio()) << " |\n";
    JsonObject row;
    row.add("table", "Tab. 4-5")
        .add("map", "2d")
        .add("planner", "rrt_star_thesis")
        .add("check", "mode_two_hypothesis")
        .add("rewire_costs", propagate ? "subtree" : "node")
        .add("goal_reattach", reattach)
        .add("mode1_length_m", o.mode1_length)
        .add("mode2_length_m", o.mode2_length)
        .add("mode1_goal_cost_m", o.mode1_cost)
        .add("mode2_goal_cost_m", o.mode2_cost);
    rows.push_back(row);
    checks.mode_two.push_back(o);
  }
  md << "\n";
  return md.str();
}

}  // namespace cosim::reproduce
