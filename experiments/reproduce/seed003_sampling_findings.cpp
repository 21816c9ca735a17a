#include "experiments/reproduce/seed003_sampling_findings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "experiments/reproduce/report_files.h"
#include "experiments/reproduce/reproduction_map.h"

namespace cosim::reproduce {

namespace {

const TableFinding* tableNamed(const std::vector<TableFinding>& findings, const char* label) {
  for (const auto& f : findings)
    if (std::string(f.table->label) == label) return &f;
  return nullptr;
}

std::string range(double lo, double hi) {
  return fmt("%.1f", 100 * lo) + "-" + fmt("%.1f", 100 * hi) + " %";
}

// RRT*FN shorter than RRT* (Tabs. 9 and 11 of the thesis).
Finding fnShorter(const std::vector<TableFinding>& findings) {
  double lo = 1e9, hi = 0, unbound_seed_gap = 0;
  int unbound = 0;
  for (const auto& f : findings) {
    const auto& t = *f.table;
    for (int k = 0; k < 4; ++k) {
      lo = std::min(lo, f.fn_length_ratio[k]);
      hi = std::max(hi, f.fn_length_ratio[k]);
      // Mode 1 with the first path before the cap: the cap never removes a node, so RRT*FN is
      // RRT* step for step; any length difference of the thesis's there is not the cap's.
      if (t.mode == 1 && f.fn_first[k] < t.caps[k]) {
        ++unbound;
        unbound_seed_gap = std::max(unbound_seed_gap, std::fabs(t.length[2 + k] / t.length[1] - 1));
      }
    }
  }
  std::string why =
      "our cap removes the childless node farthest from the goal and changes nothing else, so "
      "our RRT*FN stays within " + range(lo, hi) + " of RRT* (fewer nodes to rewire through "
      "where the cap binds)";
  if (unbound > 0)
    why += "; and in the " + std::to_string(unbound) +
           " mode-1 columns where the cap never binds (the first path comes before it), RRT*FN "
           "is RRT* step for step (ours: the same length), yet the thesis's lengths there differ "
           "from its RRT*'s by up to " +
           fmt("%.1f", 100 * unbound_seed_gap) +
           " %: its RRT*FN must differ from its RRT* in more than the cap, in a way its text "
           "does not describe";
  return checkedFinding(
      "RRT*FN's paths are shorter than RRT*'s (Tab. 9: 90.6-96.1 %, Tab. 11: 90.6-96.8 %)",
      lo < 0.97, "RRT*FN / RRT* length over all tables and caps: " + range(lo, hi), why);
}

Finding modeTwo(const std::vector<TableFinding>& findings) {
  const TableFinding *m1 = tableNamed(findings, "Tab. 4"), *m2 = tableNamed(findings, "Tab. 5");
  if (!m1 || !m2)
    return statedFinding("Mode 2 (all N nodes) leaves the 2D lengths unchanged",
                         Finding::Verdict::kDiffersUnknown, "Tab. 5 not run in --quick",
                         "run without --quick");
  const double star = m2->star_length / m1->star_length;
  const double kf = (m2->kf_ratio * m2->star_length) / (m1->kf_ratio * m1->star_length);
  return checkedFinding(
      "Generating all N nodes (mode 2) leaves the 2D path length essentially unchanged (RRT* "
      "37.10 -> 37.21 m, Tabs. 4-5)",
      std::fabs(star - 1) < 0.03,
      "our thesis RRT* mode 2 / mode 1: " + fmt("%.1f", 100 * star) + " %, Karaman-Frazzoli's " +
          fmt("%.1f", 100 * kf) + " %",
      "both choose-parent rules (the thesis's Fig. 16 and Karaman-Frazzoli's) keep shortening "
      "after the first path, as rewiring should; with the same goal rule the thesis's barely "
      "moves. Likeliest, untested: the thesis's rewiring does not pass a cost change on to the "
      "descendants (a MATLAB tree kept as parent and cost arrays needs an explicit pass for "
      "that), or its goal stays attached to the node that first reached it, where ours "
      "re-attaches the goal to any node within one step that gives a shorter path",
      false);
}

}  // namespace

std::string ratioTable(const std::vector<TableFinding>& findings) {
  std::string md =
      "\n## Ratios per table\n\n"
      "| table | RRT / RRT* length: seed | ours | KF RRT* / thesis RRT* length | RRT*FN time "
      "% of RRT* per cap: seed | ours | RRT*FN length % of RRT* per cap: seed | ours | caps that "
      "bound in mode 1 |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const TableFinding& f : findings) {
    const Seed003SamplingTable& t = *f.table;
    std::string seed_fn, ours_fn, seed_len, ours_len, bound;
    for (int k = 0; k < 4; ++k) {
      const std::string sep = k ? " / " : "";
      seed_fn += sep + fmt("%.0f", 100.0 * t.time_s[2 + k] / t.time_s[1]);
      ours_fn += sep + fmt("%.0f", 100.0 * f.fn_time_ratio[k]);
      seed_len += sep + fmt("%.1f", 100.0 * t.length[2 + k] / t.length[1]);
      ours_len += sep + fmt("%.1f", 100.0 * f.fn_length_ratio[k]);
      if (t.mode == 1 && f.fn_first[k] > t.caps[k])
        bound += (bound.empty() ? "" : ", ") + std::to_string(t.caps[k]);
    }
    if (t.mode == 2) bound = "(mode 2: all)";
    if (bound.empty()) bound = "none";
    md += "| " + std::string(t.label) + " | " + fmt("%.3f", t.length[0] / t.length[1]) + " | " +
          fmt("%.3f", f.rrt_ratio) + " | " + fmt("%.3f", f.kf_ratio) + " | " + seed_fn + " | " +
          ours_fn + " | " + seed_len + " | " + ours_len + " | " + bound + " |\n";
  }
  return md +
         "\nTime percentages: on this shared machine a run's time swings by a factor of 2-4 (the "
         "interquartile ranges above), so RRT*FN-vs-RRT* time differences of tens of percent are "
         "within the spread; the lengths are not affected.\n";
}

std::vector<Finding> samplingFindings(const std::vector<TableFinding>& findings) {
  std::vector<Finding> out;
  int rrt_longer = 0;
  double lo = 1e9, hi = 0;
  for (const auto& f : findings) {
    rrt_longer += f.rrt_ratio > 1.0;
    lo = std::min(lo, f.rrt_ratio - 1);
    hi = std::max(hi, f.rrt_ratio - 1);
  }
  const int n = static_cast<int>(findings.size());
  out.push_back(checkedFinding(
      "RRT's paths are longer than RRT*'s in every table (2D: +16 %; 3D: +6.8 to +33.8 %)",
      rrt_longer == n,
      "longer in " + std::to_string(rrt_longer) + " of " + std::to_string(n) + " tables, by " +
          range(lo, hi),
      "on our reconstructed maps RRT* does not always find the shorter homotopy class"));
  out.push_back(fnShorter(findings));
  if (const TableFinding* t10 = tableNamed(findings, "Tab. 10"))
    out.push_back(checkedFinding(
        "RRT*FN with cap 400 takes 41 % of RRT*'s time on 3D map 2, set 1 (Tab. 10)",
        t10->fn_time_ratio[0] < 0.7, fmt("%.0f", 100 * t10->fn_time_ratio[0]) + " %",
        "capping the tree makes the thesis's MATLAB cheaper per node (it computes the distance "
        "to every node), while in our C++ the collision checks dominate each iteration, so a "
        "smaller tree saves little; the linear-scan check above gives every query the thesis's "
        "kind of cost and still shows no such saving, and removing the farthest leaf does not "
        "make the tree reach the goal sooner"));
  out.push_back(modeTwo(findings));
  if (const TableFinding* m1 = tableNamed(findings, "Tab. 4"), *m2 = tableNamed(findings, "Tab. 5");
      m1 && m2)
    out.push_back(checkedFinding(
        "Mode 2 costs about 1.6-1.7x the time of mode 1 in 2D (RRT* 4.92 vs 2.97 s, Tabs. 4-5)",
        m2->star_time_ms / m1->star_time_ms > 1.3 && m2->star_time_ms / m1->star_time_ms < 2.2,
        "our RRT* (thesis) median time ratio " + fmt("%.2f", m2->star_time_ms / m1->star_time_ms) +
            "x",
        "our mode-1 RRT* stops at its first path, after " + fmt("%.0f", m1->star_first) +
            " of the N = 1000 nodes (median), so mode 2 adds most of the work; the thesis's "
            "mode 1 took 60 % of its mode-2 time, so its first path came late on its map. "
            "Where the first path comes depends on the layout, and ours is a rebuild"));
  out.push_back(statedFinding("The maps' obstacle layouts (figures only in the thesis)",
                              Finding::Verdict::kDiffers, "absolute lengths differ",
                              "the maps are equivalents rebuilt from sizes, starts, goals and "
                              "descriptions (drawn above); compare the ratio columns"));
  return out;
}

std::string samplingMaps(const Options& options, const std::vector<Seed003Map>& maps,
                         const std::map<std::string, BestPaths>& best) {
  const char* labels[4] = {"RRT", "RRT* (thesis)", "RRT* (Karaman-Frazzoli)", "RRT*FN (thesis)"};
  std::vector<std::string> files, how;
  int index = 0;
  for (const Seed003Map& m : maps) {
    const auto it = best.find(m.name);
    if (it == best.end()) continue;
    const OccupancyGrid grid = seed003Grid(m);
    ReproductionMap fig = gridMap(m.name + (m.planar ? "" : " (seen from above)") +
                                      ", shortest path of each planner over all runs",
                                  grid, grid.cellOf(m.start), grid.cellOf(m.goal));
    fig.unit = "m";
    for (int k = 0; k < 4; ++k) {
      const Path& p = it->second.path[k];
      if (p.empty()) continue;
      MapPath line{std::string(labels[k]) + " " + fmt("%.1f", p.length()) + " m", {}};
      for (const auto& w : p.waypoints) line.points.emplace_back(w.x(), w.y());
      fig.paths.push_back(line);
    }
    files.push_back(writeReproductionMap(options.out_dir, "seed003-sampling", ++index, fig));
    how.push_back(m.name +
                  ": an equivalent rebuilt from the thesis's figure only (size, start, "
                  "goal and description from the text)");
  }
  return mapFiguresMarkdown(files, how);
}

}  // namespace cosim::reproduce
