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
      "our RRT*FN stays within " +
      range(lo, hi) +
      " of RRT* (fewer nodes to rewire through "
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

// Mode 2 barely shortening the 2D path (Tabs. 4-5), against the thesis's two candidate causes as
// measured in the "Mode 2" section.
Finding modeTwo(const SamplingChecks& checks) {
  const Seed003SamplingTable& m1 = kSeed003SamplingTables[0];
  const Seed003SamplingTable& m2 = kSeed003SamplingTables[1];
  const char* claim =
      "Generating all N nodes (mode 2) leaves the 2D path length essentially unchanged (RRT* "
      "37.10 -> 37.21 m, Tabs. 4-5)";
  if (checks.mode_two.empty())
    return statedFinding(claim, Finding::Verdict::kDiffersUnknown, "Tabs. 4-5 not run",
                         "run the full reproduction");
  const double seed_ratio = m2.length[1] / m1.length[1];
  const ModeTwoOutcome& usual = checks.mode_two.front();
  std::string ours = "our thesis RRT* mode 2 / mode 1: " + fmt("%.1f", 100 * usual.ratio()) + " %";
  std::string reproducing, tried;
  for (std::size_t i = 1; i < checks.mode_two.size(); ++i) {
    const ModeTwoOutcome& o = checks.mode_two[i];
    tried += (tried.empty() ? "" : ", ") + o.rules + " " + fmt("%.1f", 100 * o.ratio()) +
             " % (goal's stored cost " + fmt("%.1f", 100 * o.costRatio()) + " %)";
    if (std::fabs(o.ratio() - seed_ratio) < 0.03)
      reproducing += (reproducing.empty() ? "" : "; ") + o.rules + ", the path itself";
    else if (std::fabs(o.costRatio() - seed_ratio) < 0.03)
      reproducing += (reproducing.empty() ? "" : "; ") + o.rules +
                     ", if the thesis printed the goal's stored cost rather than the path's length";
  }
  ours += "; with the thesis's candidate causes switched on: " + tried;
  if (!reproducing.empty())
    return checkedFinding(claim, std::fabs(usual.ratio() - seed_ratio) < 0.03, ours,
                          "our RRT* keeps shortening after the first path, as rewiring should; "
                          "the thesis's " +
                              fmt("%.1f", 100 * seed_ratio) +
                              " % appears within 3 points only with " + reproducing +
                              " (section \"Mode 2\" above)");
  return checkedFinding(
      claim, std::fabs(usual.ratio() - seed_ratio) < 0.03, ours,
      "both rewiring rules keep shortening after the first path, and neither of the thesis's "
      "candidate causes, alone or together, brings mode 2 within 3 points of its " +
          fmt("%.1f", 100 * seed_ratio) +
          " %, measured on the path or on the goal's stored "
          "cost (section \"Mode 2\" above)",
      false);
}

// True where RRT*FN's time at cap k is below RRT*'s with the interquartile ranges apart.
bool clearlyFaster(const TableFinding& f, int k) {
  return f.fn_time_q3[k] < f.star_time_q1;
}
bool clearlySlower(const TableFinding& f, int k) {
  return f.fn_time_q1[k] > f.star_time_q3;
}

// Sec. 4.1.2: RRT*FN faster than RRT* at caps N/5 to N/3 in almost every 3D test, mainly mode 2.
Finding capWindow(const std::vector<TableFinding>& findings) {
  int faster[3] = {0, 0, 0}, slower[3] = {0, 0, 0}, columns[3] = {0, 0, 0};  // mode 1, 2, 3D all
  int bound_mode1 = 0;  // mode-1 columns where the cap binds (the first path comes after it)
  for (const auto& f : findings) {
    if (std::string(f.table->map) == "2d") continue;
    for (int k = 0; k < 2; ++k) {  // caps N/5 and N/4 (N/3 lies between the 2nd and 3rd cap)
      const int m = f.table->mode - 1;
      if (m == 0) bound_mode1 += f.fn_first[k] > f.table->caps[k];
      ++columns[m], ++columns[2];
      faster[m] += clearlyFaster(f, k), faster[2] += clearlyFaster(f, k);
      slower[m] += clearlySlower(f, k), slower[2] += clearlySlower(f, k);
    }
  }
  auto share = [](int a, int n) { return std::to_string(a) + " of " + std::to_string(n); };
  return checkedFinding(
      "RRT*FN with a cap of N/5 to N/3 is faster than RRT* in almost every 3D test, mainly in "
      "mode 2 (sec. 4.1.2)",
      columns[2] > 0 && faster[2] >= 0.8 * columns[2],
      "3D, caps N/5 and N/4: faster with the interquartile ranges apart in " +
          share(faster[2], columns[2]) + " columns (mode 1: " + share(faster[0], columns[0]) +
          ", mode 2: " + share(faster[1], columns[1]) + "), slower in " +
          share(slower[2], columns[2]),
      "in mode 1 our first path comes before the cap in " +
          std::to_string(columns[0] - bound_mode1) + " of " + std::to_string(columns[0]) +
          " of those columns, where RRT*FN is RRT* step for step and cannot be faster; where the "
          "cap binds (the other " +
          std::to_string(bound_mode1) +
          " mode-1 columns and all of mode 2) it gives clear speed-ups in " +
          share(faster[0] + faster[1], bound_mode1 + columns[1]) +
          " (mode 2: " + share(faster[1], columns[1]) +
          ", the thesis's \"mainly in mode 2\"), fewer than the thesis's; the linear-scan check "
          "(Tab. 10) rules out its per-node scans as the difference, and no other was found",
      false);
}

// Tab. 5: in 2D mode 2, caps 200 and 250 (N/5, N/4) take 76.8 and 86.7 % of RRT*'s time.
Finding twoDimensionalCapWindow(const std::vector<TableFinding>& findings) {
  const TableFinding* t5 = tableNamed(findings, "Tab. 5");
  const char* claim =
      "In 2D mode 2, RRT*FN with caps 200 and 250 (N/5, N/4) takes 76.8 and 86.7 % of RRT*'s "
      "time, larger caps more than RRT* (Tab. 5)";
  if (!t5)
    return statedFinding(claim, Finding::Verdict::kDiffersUnknown, "Tab. 5 not run",
                         "run the full reproduction");
  const bool window_faster = clearlyFaster(*t5, 0) && clearlyFaster(*t5, 1);
  const bool larger_not = !clearlyFaster(*t5, 2) && !clearlyFaster(*t5, 3);
  auto range = [&](int k) {
    return fmt("%.1f", 100 * t5->fn_time_ratio[k]) + " % [" + fmt("%.1f", t5->fn_time_q1[k]) + "-" +
           fmt("%.1f", t5->fn_time_q3[k]) + " ms]";
  };
  return checkedFinding(
      claim, window_faster && larger_not,
      "ours: caps 200, 250 " + range(0) + ", " + range(1) + "; caps 350, 500 " + range(2) + ", " +
          range(3) + "; RRT* [" + fmt("%.1f", t5->star_time_q1) + "-" +
          fmt("%.1f", t5->star_time_q3) + " ms]",
      window_faster ? "our larger caps are not slower than RRT*: the thesis put their extra time "
                      "down to its farthest-from-goal search, which our heap of leaves does in "
                      "logarithmic time"
                    : "the medians differ by less than the spread of the runs: the linear-scan "
                      "check (Tab. 10) rules out the thesis's per-node scans as the saving, and "
                      "what else made its capped 2D runs cheaper is not in its text",
      window_faster);
}

// Sec. 4.1.2: caps below N/5 fail in more than 90 % of runs (2D).
Finding smallCaps(const SamplingChecks& checks) {
  int runs = 0, successes = 0;
  std::string per;
  for (const SmallCapOutcome& c : checks.small_caps) {
    runs += c.runs, successes += c.successes;
    per += (per.empty() ? "" : ", ") + std::string(c.table->label) + " cap " +
           std::to_string(c.cap) + ": " + std::to_string(c.successes) + "/" +
           std::to_string(c.runs);
  }
  const double fail = runs ? 1.0 - static_cast<double>(successes) / runs : 0.0;
  return checkedFinding(
      "RRT*FN with a cap below N/5 fails in more than 90 % of runs (2D, sec. 4.1.2)", fail > 0.9,
      "ours fails in " + fmt("%.0f", 100 * fail) + " % (" + per + ")",
      "our cap removes the childless node farthest from the goal (Script 9's policy), which "
      "never cuts the branch that grows towards the goal, so the capped tree still reaches it; "
      "what made the thesis's capped trees fail is not in its text",
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
  int faster = 0, slower = 0, columns = 0;
  for (const TableFinding& f : findings)
    for (int k = 0; k < 4; ++k)
      ++columns, faster += clearlyFaster(f, k), slower += clearlySlower(f, k);
  return md +
         "\nTime percentages compare medians. RRT*FN is faster than RRT* with the "
         "interquartile ranges apart (its upper quartile below RRT*'s lower one) in " +
         std::to_string(faster) + " of " + std::to_string(columns) + " columns, slower so in " +
         std::to_string(slower) + "; in the rest the ranges overlap.\n";
}

std::vector<Finding> samplingFindings(const std::vector<TableFinding>& findings,
                                      const SamplingChecks& checks) {
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
        "the linear-scan check above gives every query the thesis's kind of cost (the distance "
        "to every node) and still shows no such saving, and removing the farthest leaves " +
            std::string(t10->fn_first[0] < 0.9 * t10->star_first ? "makes" : "does not make") +
            " our tree reach the goal markedly sooner (first path after " +
            fmt("%.0f", t10->fn_first[0]) + " nodes with the cap, " + fmt("%.0f", t10->star_first) +
            " without; the thesis's explanation is that the cap concentrates sampling near start "
            "and goal), so what saved the thesis's time is not in our rebuild",
        false));
  out.push_back(capWindow(findings));
  out.push_back(twoDimensionalCapWindow(findings));
  if (!checks.small_caps.empty()) out.push_back(smallCaps(checks));
  out.push_back(modeTwo(checks));
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
