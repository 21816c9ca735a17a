#include "experiments/reproduce/seed000_msac_findings.h"

#include <cmath>

#include "experiments/reproduce/reproduction_map.h"

namespace cosim::reproduce {

namespace {

std::string n2(double v) {
  return seed000Number(v, 2);
}

bool allOptimal(const std::vector<Seed000Column>& cols, double optimum) {
  for (const auto& c : cols)
    if (c.ours.failures > 0 || std::fabs(c.ours.mean_length - optimum) > 0.01) return false;
  return true;
}

std::string triple(const std::vector<Seed000Column>& cols, double (*value)(const Seed000Stats&),
                   int decimals) {
  std::string s;
  for (std::size_t k = 0; k < cols.size(); ++k)
    s += (k ? " / " : "") + seed000Number(value(cols[k].ours), decimals);
  return s;
}

double meanMs(const Seed000Stats& s) {
  return s.mean_ms;
}
double meanLength(const Seed000Stats& s) {
  return s.mean_length;
}
double moves(const Seed000Stats& s) {
  return s.mean_steps;
}

// Time rising with m (Tables 6.4-6.7), with the search effort that explains ours.
Finding timeWithM(const MsacResults& r) {
  int rising = 0;
  for (const auto& cols : r.m)
    rising +=
        cols[0].ours.mean_ms < cols[1].ours.mean_ms && cols[1].ours.mean_ms < cols[2].ours.mean_ms;
  const auto& s2 = r.m[0];  // Table 6.4, scene 2
  std::string work;
  for (std::size_t k = 0; k < s2.size(); ++k)
    work += (k ? " / " : "") + seed000Number(2 * std::stoi(s2[k].label) * s2[k].ours.mean_steps, 0);
  return checkedFinding(
      "Time rises with the number of ants m on every scene (Tables 6.4-6.7, e.g. scene 2 "
      "2.5 / 3.7 / 6.2 s for m = 2 / 4 / 8)",
      rising == static_cast<int>(r.m.size()),
      "rising in " + std::to_string(rising) + " of " + std::to_string(r.m.size()) +
          " tables; scene 2 (Table 6.4) " + triple(s2, meanMs, 3) + " ms",
      "more scouts meet sooner: on scene 2 our groups meet after " + triple(s2, moves, 0) +
          " synchronised steps (all MAX iterations) at m = 2 / 4 / 8, so the ant moves made "
          "(2m x steps: " +
          work +
          ") grow far less than m, and our time follows those moves; "
          "the thesis's MATLAB times grow almost in proportion to m, as a fixed cost per ant "
          "and step would make them");
}

Finding sceneTwoCost(const MsacResults& r) {
  const Seed000Stats &s2 = r.m[0][1].ours, &s1 = r.m[2][1].ours;  // m = 4, MAX 3
  const double ratio = s2.mean_ms / s1.mean_ms;
  return checkedFinding(
      "Scene 2 costs far more time than scene 1 (m 4, MAX 3: 3.682 vs 0.100 s, about 37x)",
      ratio > 10,
      "ours " + seed000Number(s2.mean_ms, 3) + " vs " + seed000Number(s1.mean_ms, 3) + " ms, " +
          seed000Number(ratio, 1) + "x",
      "the time follows the search: our scouts take " + seed000Number(s2.mean_steps, 0) +
          " synchronised steps (3 iterations) on scene 2 against " +
          seed000Number(s1.mean_steps, 0) + " on scene 1, " +
          seed000Number(s2.mean_steps / std::max(1.0, s1.mean_steps), 1) +
          "x, and the thesis's unprocessed scene-2 paths average 1018 cells (ours " +
          n2(r.post_scene2[1].ours.mean_length) +
          "), so its scouts wandered longer in its cup than ours do in our rebuild of a map we "
          "could not see");
}

Finding postProcessingTime(const MsacResults& r) {
  const double q1 = r.post_scene1[0].ours.mean_ms / r.post_scene1[1].ours.mean_ms;
  const double q2 = r.post_scene2[0].ours.mean_ms / r.post_scene2[1].ours.mean_ms;
  const auto steps = [](const std::vector<Seed000Column>& c) {
    return seed000Number(c[0].ours.mean_steps, 0) + " / " + seed000Number(c[1].ours.mean_steps, 0);
  };
  return checkedFinding(
      "Post-processing costs time: +17 % on scene 1 (0.1010 vs 0.0860 s), +20 % on scene 2 "
      "(3.694 vs 3.070 s) (Tables 6.2-6.3)",
      q1 > 1.05 && q2 > 1.05,
      "with / without: scene 1 " + seed000Number(100 * (q1 - 1), 0) + " %, scene 2 " +
          seed000Number(100 * (q2 - 1), 0) + " %",
      "processing only changes the joined paths, not the walks (synchronised steps with / "
      "without: scene 1 " +
          steps(r.post_scene1) + ", scene 2 " + steps(r.post_scene2) +
          "), so the difference is processing's own cost: one pass over the joined path at each "
          "meeting, against 2m ant moves per step in compiled code; in interpreted MATLAB the "
          "same loops cost a fifth of the run");
}

// Tables 6.4-6.5: how much longer one iteration's path is than the best of three.
Finding maxOnePenalty(const MsacResults& r) {
  const double seed_gap[3] = {5.0, 11.1, 5.2};  // Table 6.5: (average - minimum) / average, %
  std::string pct, outside;
  int in_range = 0, wider = 0, out = 0;
  for (std::size_t k = 0; k < r.m[0].size(); ++k) {
    const Seed000Stats &three = r.m[0][k].ours, &one = r.m[1][k].ours;
    const double p = 100.0 * (one.mean_length / three.mean_length - 1.0);
    pct += (k ? " / " : "") + seed000Number(p, 1);
    if (p > 0 && p < 10) {
      ++in_range;
      continue;
    }
    const double gap = 100.0 * (1.0 - one.min_length / one.mean_length);
    ++out;
    wider += gap > seed_gap[k];
    outside += std::string(outside.empty() ? "" : "; ") + "m = " + r.m[1][k].label + ": " +
               seed000Number(p, 1) + " %, its MAX-1 average " + seed000Number(gap, 1) +
               " % above its minimum (the thesis's " + seed000Number(seed_gap[k], 1) + " %)";
  }
  return checkedFinding(
      "Scene 2: MAX 1 gives 3.8 / 6.9 / 4.6 % longer averages than MAX 3 for m = 2 / 4 / 8 "
      "(Tables 6.4-6.5)",
      in_range == 3, "MAX 1 longer by " + pct + " %",
      "MAX 3 keeps the best of three iterations, which gains more the wider one iteration's "
      "paths spread, and where ours is outside 0-10 % they spread wider than the thesis's (" +
          outside + "), on a cup rebuilt without seeing the thesis's",
      wider == out);
}

// Table 6.4: m = 4 gives the shortest average and minimum on scene 2.
Finding bestM(const MsacResults& r) {
  const auto& t = r.m[0];
  std::size_t best = 0, best_min = 0;
  for (std::size_t k = 1; k < t.size(); ++k) {
    if (t[k].ours.mean_length < t[best].ours.mean_length) best = k;
    if (t[k].ours.min_length < t[best_min].ours.min_length) best_min = k;
  }
  double se = 0;  // two standard errors of a 10-run mean, the widest of the three
  for (const auto& c : t)
    se = std::max(se, 2.0 * c.ours.sd_length / std::sqrt(std::max(1, c.ours.runs)));
  double spread = 0;
  for (const auto& c : t) spread = std::max(spread, c.ours.mean_length - t[best].ours.mean_length);
  return checkedFinding(
      "Scene 2, MAX 3: m = 4 gives the shortest average (146.95; m = 8 under 2 % longer, m = 2 "
      "about 4 %) (Table 6.4)",
      t[best].label == "4",
      "shortest average at m = " + t[best].label + ", shortest minimum at m = " +
          t[best_min].label + " (averages " + triple(t, meanLength, 2) + ")",
      spread < se ? "our averages lie within " + n2(spread) +
                        " of each other, less than two standard errors of a 10-run mean (" +
                        n2(se) + "), so 10 runs do not order them"
                  : "more scouts meet sooner on our rebuilt cup, each meeting nearer the "
                    "straight line between the groups (averages " +
                        triple(t, meanLength, 2) + ")",
      spread < se);
}

// Table 6.5: MAX 1 takes about a third of MAX 3's time.
Finding maxOneTime(const MsacResults& r) {
  std::string q, steps;
  int third = 0;
  for (std::size_t k = 0; k < r.m[0].size(); ++k) {
    const double ratio = r.m[1][k].ours.mean_ms / r.m[0][k].ours.mean_ms;
    third += ratio > 0.25 && ratio < 0.45;
    q += (k ? " / " : "") + seed000Number(ratio, 2);
    steps += (k ? " / " : "") + seed000Number(r.m[1][k].ours.mean_steps, 0) + " of " +
             seed000Number(r.m[0][k].ours.mean_steps, 0);
  }
  return checkedFinding(
      "Scene 2: MAX 1 takes about a third of MAX 3's time (0.875 / 1.212 / 1.937 against "
      "2.521 / 3.682 / 6.167 s) (Tables 6.4-6.5)",
      third == 3, "MAX 1 / MAX 3 time for m = 2 / 4 / 8: " + q,
      "our time follows the synchronised steps (MAX 1 against MAX 3: " + steps +
          "), and the later iterations keep the first one's dead-end marks (§4.3.2), so they "
          "need fewer steps than the first");
}

// §4.3's iteration end against the literal step 6: the steps the scouts take.
Finding iterationEnd(const MsacResults& r) {
  const Seed000Stats &meet = r.ends.stats[0][0], &literal = r.ends.stats[1][0];
  return checkedFinding(
      "An iteration ends when the two groups meet or after S_max steps (§4.3); scene 1 took "
      "0.100 s with m 4, MAX 3, under a tenth of scene 2's time (Tables 6.4, 6.6)",
      meet.mean_steps < 0.1 * literal.mean_steps,
      "scene 1, m 4, MAX 3: " + seed000Number(meet.mean_steps, 0) + " synchronised steps, " +
          seed000Number(meet.mean_ms, 3) + " ms; with the literal step 6 (only a shorter path " +
          "ends an iteration) " + seed000Number(literal.mean_steps, 0) + " steps, " +
          seed000Number(literal.mean_ms, 3) + " ms",
      "the meetings of our later iterations give shorter paths, so both rules end them alike");
}

// §6.1.4's scene 3: the thesis's MSAC detours where [41]'s path runs straight down column 50;
// its author proposes a wider-range smoothing.
std::vector<Finding> scene3Findings(const MsacResults& r) {
  const Scene3Results& s = r.scene3;
  const int runs = s.stats[0].runs;
  std::vector<Finding> f;
  f.push_back(checkedFinding(
      "Scene 3: the thesis's MSAC paths make a detour on the right side (column 50), where "
      "[41]'s runs straight, with any parameters (§6.1.4; our scene 3 is built, the figure is "
      "not in the text)",
      s.straight[0] < runs,
      "light smoothing: no detour on the right side in " + std::to_string(s.straight[0]) + " of " +
          std::to_string(runs) + " runs; average " + n2(s.stats[0].mean_length) +
          " against the optimum " + n2(s.optimum),
      "on our build the scouts come down the right side's corridor along its wall, straight, "
      "and the light smoothing keeps that; our paths' excess over the optimum lies elsewhere "
      "(see the map)"));
  f.push_back(checkedFinding(
      "Scene 3: a wider-range smoothing would remove such detours (the thesis's proposal, "
      "§6.1.4)",
      s.stats[1].mean_length < s.stats[0].mean_length - 1e-9 && s.straight[1] >= s.straight[0],
      "smoothing over " + std::to_string(kWideSmoothing) + " nodes: average " +
          n2(s.stats[1].mean_length) + " (light: " + n2(s.stats[0].mean_length) +
          "), no detour on the right side in " + std::to_string(s.straight[1]) + " of " +
          std::to_string(runs) + " runs",
      "the wider smoothing does not shorten our paths"));
  return f;
}

}  // namespace

std::vector<Finding> msacFindings(const MsacResults& r, const Seed000SceneSet& scenes) {
  std::vector<Finding> f;
  const double tabu = r.tabu[0].ours.mean_ms / r.tabu[2].ours.mean_ms;
  f.push_back(checkedFinding(
      "The group+ant tabu table (version 3) makes MSAC about 5.6x faster than version 1 "
      "(Table 6.1)",
      tabu > 2, "version 1 / version 3 time " + seed000Number(tabu, 1) + "x",
      "in C++ version 1's look-up of a meeting in every path of the other group is a short loop "
      "over at most 2m paths, not the interpreted search that made it slow in MATLAB"));
  f.push_back(checkedFinding(
      "The free scene: the optimum 65.05 in every run for m = 2, 4, 8 (Table 6.7)",
      allOptimal(r.m[3], scenes.opt_free), "mean lengths " + triple(r.m[3], meanLength, 2),
      "some run missed the optimum"));
  f.push_back(checkedFinding(
      "Scene 1: always 73.84, with or without post-processing (Tables 6.2, 6.6)",
      allOptimal(r.m[2], scenes.opt1) && allOptimal(r.post_scene1, scenes.opt1),
      "mean lengths m = 2/4/8: " + triple(r.m[2], meanLength, 2) +
          "; with / without "
          "processing: " +
          triple(r.post_scene1, meanLength, 2),
      "our rebuilt scene 1 has the thesis's optimum but not necessarily its layout (figure not "
      "in the text), and some of our runs end above it"));
  const double shorten = r.post_scene2[1].ours.mean_length / r.post_scene2[0].ours.mean_length;
  f.push_back(checkedFinding(
      "Scene 2: post-processing shortens the average path about 6.8x (1018 -> 149, Table 6.3)",
      shorten > 3,
      "ours " + n2(r.post_scene2[1].ours.mean_length) + " -> " +
          n2(r.post_scene2[0].ours.mean_length) + ", " + seed000Number(shorten, 1) + "x",
      "our unprocessed scouts' paths in the rebuilt cup are shorter to begin with"));
  f.push_back(postProcessingTime(r));
  f.push_back(timeWithM(r));
  f.push_back(sceneTwoCost(r));
  const double fail = 100.0 * r.max1_m1_scene2.failures / std::max(1, r.max1_m1_scene2.runs);
  f.push_back(checkedFinding(
      "Scene 2, MAX 1 and m 1: no path in about 30 % of runs (§6.1.4)", fail >= 15 && fail <= 45,
      seed000Number(fail, 0) + " % of " + std::to_string(r.max1_m1_scene2.runs) + " runs",
      "whether one scout pair meets within S_max = 1250 steps depends on the cup's shape, and "
      "ours is a rebuild"));
  f.push_back(maxOnePenalty(r));
  f.push_back(bestM(r));
  f.push_back(maxOneTime(r));
  f.push_back(iterationEnd(r));
  for (Finding& x : scene3Findings(r)) f.push_back(x);
  return f;
}

std::string msacMaps(const Options& options, const Seed000SceneSet& scenes, const MsacResults& r) {
  const std::string name = "seed000-msac";
  std::vector<std::string> files = {
      drawSeed000Scene(options, name, 1, scenes.free_scene,
                       {{"MSAC m 4, MAX 3", r.m[3][1].ours.best_path}}),
      drawSeed000Scene(options, name, 2, scenes.scene1,
                       {{"MSAC m 4, MAX 3", r.m[2][1].ours.best_path}}),
      drawSeed000Scene(options, name, 3, scenes.scene2,
                       {{"MSAC m 4, MAX 3, processed", r.m[0][1].ours.best_path},
                        {"MSAC m 4, MAX 3, unprocessed", r.post_scene2[1].ours.best_path}}),
      drawSeed000Scene(options, name, 4, r.scene3.scene,
                       {{"MSAC m 4, MAX 3, light smoothing", r.scene3.stats[0].best_path},
                        {"MSAC m 4, MAX 3, wider smoothing", r.scene3.stats[1].best_path}})};
  return mapFiguresMarkdown(files, {scenes.free_scene.origin, scenes.scene1.origin,
                                    scenes.scene2.origin, r.scene3.scene.origin});
}

}  // namespace cosim::reproduce
