// Reproduction of seed 000's MSAC experiments (Pěňčík 2014, §6.1, Tables 6.1-6.7, claims 1-6):
// tabu table versions, path post-processing, number of ants m and iterations MAX on the free
// 50x50 scene and on scenes 1 and 2 (rebuilt, see seed000_scenes.h). Unconditional diagonals and
// S_max = 1250 as in the seed; 10 runs per setting unless --runs says otherwise.
#include <cmath>
#include <limits>
#include <sstream>

#include "experiments/reproduce/agreement_section.h"
#include "experiments/reproduce/reproduction_map.h"
#include "experiments/reproduce/seed000_msac_findings.h"
#include "experiments/reproduce/seed000_runs.h"
#include "planning/swarm/msac.h"

namespace cosim::reproduce {

namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

// What every table of this reproduction runs on: the scenes, their optima, the runs and seed.
struct MsacSetting {
  const Options& options;
  int runs;
  std::uint64_t seed;
  const Seed000SceneSet& scenes;
};

// The thesis's MSAC settings: S_max 1250, unconditional diagonals, an iteration ends when the
// groups meet (§4.3).
MsacParams thesisMsac(int m, int max_iterations, bool post_processing, int tabu_version) {
  MsacParams p;
  p.ants = m;
  p.iterations = max_iterations;
  p.s_max = 1250;
  p.post_processing = post_processing;
  p.tabu_version = tabu_version;
  p.conditional_diagonal = false;
  p.iteration_end = MsacIterationEnd::Meeting;
  return p;
}

Seed000Stats msacRuns(const Seed000Scene& scene, int m, int max_iterations, bool post_processing,
                      int tabu_version, int runs, std::uint64_t seed) {
  Msac msac(thesisMsac(m, max_iterations, post_processing, tabu_version));
  return runSeed000(msac, scene, runs, seed);
}

// Which rule ends an iteration: the thesis's (the groups meet) against the literal step 6 (only
// a shorter path), m 4, MAX 3, on scenes 1 and 2.
IterationEndResults iterationEndSection(const MsacSetting& at, std::ostringstream& out,
                                        std::vector<JsonObject>& rows) {
  IterationEndResults r;
  const Seed000Scene* scenes[2] = {&at.scenes.scene1, &at.scenes.scene2};
  for (int rule = 0; rule < 2; ++rule)
    for (int k = 0; k < 2; ++k) {
      MsacParams p = thesisMsac(4, 3, true, 3);
      p.iteration_end = rule == 0 ? MsacIterationEnd::Meeting : MsacIterationEnd::ShorterPath;
      Msac msac(p);
      r.stats[rule][k] = runSeed000(msac, *scenes[k], at.runs, at.seed);
    }
  out << "### What ends an iteration (§4.3), m 4, MAX 3\n\nThe thesis: an iteration ends when "
         "an ant of one group comes upon the path of the other group, or after S_max steps "
         "(used in every other table). Step 6 read literally: only a meeting that gives a "
         "shorter path than the best so far ends it, so from the second iteration on the scouts "
         "walk on, often to S_max. Steps are synchronised steps over all MAX iterations.\n\n"
         "| iteration ends | scene 1 time [ms] | scene 1 steps | scene 1 avg. length | scene 2 "
         "time [ms] | scene 2 steps | scene 2 avg. length |\n|---|---|---|---|---|---|---|\n";
  for (int rule = 0; rule < 2; ++rule) {
    const char* name = rule == 0 ? "groups meet (thesis)" : "shorter path (step 6 literally)";
    out << "| " << name << " |";
    JsonObject row;
    row.add("table", "iteration end").add("rule", name);
    for (int k = 0; k < 2; ++k) {
      const Seed000Stats& st = r.stats[rule][k];
      out << " " << seed000Number(st.mean_ms, 3) << " | " << seed000Number(st.mean_steps, 0)
          << " | " << seed000Number(st.mean_length, 2) << " |";
      const std::string scene = k == 0 ? "scene1_" : "scene2_";
      row.add(scene + "time_ms", st.mean_ms)
          .add(scene + "steps", st.mean_steps)
          .add(scene + "mean_length", st.mean_length);
    }
    out << "\n";
    rows.push_back(row);
  }
  out << "\n";
  return r;
}

// Whether a path makes no detour down the right side of scene 3: its part between rows 12 and 46
// is as long as the octile distance between that part's ends.
bool straightDownTheEdge(const std::vector<Cell>& cells) {
  std::size_t first = cells.size(), last = 0;
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (cells[i].y >= 12 && cells[i].y <= 46) {
      first = std::min(first, i);
      last = i;
    }
  if (first >= cells.size()) return false;
  const std::vector<Cell> part(cells.begin() + first, cells.begin() + last + 1);
  const double dx = std::abs(part.front().x - part.back().x),
               dy = std::abs(part.front().y - part.back().y);
  const double octile = std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy);
  return gridPathLength(part) < octile + 1e-9;
}

// §6.1.4, scene 3: the seed's light smoothing against the wider-range smoothing its author
// proposes, m 4, MAX 3.
Scene3Results scene3Section(const MsacSetting& at, std::ostringstream& out,
                            std::vector<JsonObject>& rows) {
  Scene3Results r;
  r.scene = seed000Scene3();
  r.optimum = seed000Optimum(r.scene, false);
  out << "### Scene 3 (§6.1.4), m 4, MAX 3\n\n"
      << r.scene.origin << "; optimum " << seed000Number(r.optimum, 2)
      << ". The thesis gives no table: [41]'s path runs straight down column 50, the thesis's "
         "MSAC paths do not, with any parameters, and its author proposes a wider-range "
         "smoothing. 'No detour' counts the runs whose path between rows 12 and 46 (the right "
         "side) is as short as the octile distance between its ends.\n\n| smoothing | runs | avg. "
         "length | min. length | no detour "
         "on the right side |\n|---|---|---|---|---|\n";
  for (int k = 0; k < 2; ++k) {
    MsacParams p = thesisMsac(4, 3, true, 3);
    p.smoothing_range = k == 0 ? 1 : kWideSmoothing;
    Msac msac(p);
    r.stats[k] = runSeed000(msac, r.scene, at.runs, at.seed);
    for (int i = 0; i < at.runs; ++i) {
      GridQuery q;
      q.grid = &r.scene.grid;
      q.start = r.scene.start;
      q.goal = r.scene.goal;
      q.seed = at.seed + static_cast<std::uint64_t>(i);
      const GridPlanResult run = msac.solveGrid(q, StopToken::untimed());
      r.straight[k] += run.success && straightDownTheEdge(run.cells);
    }
    const std::string name = k == 0 ? "light (the thesis's)"
                                    : "wider, over " + std::to_string(kWideSmoothing) + " nodes";
    out << "| " << name << " | " << at.runs << " | " << seed000Number(r.stats[k].mean_length, 2)
        << " | " << seed000Number(r.stats[k].min_length, 2) << " | " << r.straight[k] << "/"
        << at.runs << " |\n";
    JsonObject row;
    row.add("table", "scene 3 (6.1.4)")
        .add("smoothing", name)
        .add("optimum", r.optimum)
        .add("mean_length", r.stats[k].mean_length)
        .add("min_length", r.stats[k].min_length)
        .add("straight_runs", r.straight[k])
        .add("runs", at.runs);
    rows.push_back(row);
  }
  out << "\n";
  return r;
}

// Table 6.1: tabu table versions (time only; 100 searches in the seed).
std::vector<Seed000Column> tabuTable(const MsacSetting& at, std::ostringstream& out,
                                     std::vector<JsonObject>& rows) {
  const int runs = at.runs;
  const std::uint64_t seed = at.seed;
  const Seed000Scene& scene1 = at.scenes.scene1;
  std::vector<Seed000Column> cols;
  const double seed_t[3] = {0.586, 0.130, 0.104};
  for (int v = 1; v <= 3; ++v)
    cols.push_back({"version " + std::to_string(v), seed_t[v - 1], kNone, kNone,
                    msacRuns(scene1, 4, 3, true, v, at.options.quick ? runs : 10 * runs, seed)});
  out << seed000Table("Table 6.1: tabu table version, scene 1 (MAX 3, m 4)", "tabu table", cols,
                      at.scenes.opt1, rows);
  out << "Seed: version 3 is 5.6x faster than version 1; ours: "
      << seed000Number(cols[0].ours.mean_ms / cols[2].ours.mean_ms, 1) << "x.\n\n";
  return cols;
}

// Tables 6.2 and 6.3: post-processing on scene 1 or 2.
std::vector<Seed000Column> postProcessingTable(const MsacSetting& at, int scene_no,
                                               std::ostringstream& out,
                                               std::vector<JsonObject>& rows) {
  const int runs = at.runs;
  const std::uint64_t seed = at.seed;
  const Seed000Scene &scene1 = at.scenes.scene1, &scene2 = at.scenes.scene2;
  const double opt1 = at.scenes.opt1, opt2 = at.scenes.opt2;
  std::vector<Seed000Column> cols;
  const Seed000Scene& scene = scene_no == 1 ? scene1 : scene2;
  const double seed_t[2] = {scene_no == 1 ? 0.1010 : 3.694, scene_no == 1 ? 0.0860 : 3.070};
  const double seed_mean[2] = {scene_no == 1 ? 73.84 : 149.12, scene_no == 1 ? 73.84 : 1018.16};
  const double seed_min[2] = {scene_no == 1 ? 73.84 : 140.17, scene_no == 1 ? 73.84 : 808.67};
  for (int k = 0; k < 2; ++k)
    cols.push_back({k == 0 ? "yes" : "no", seed_t[k], seed_mean[k], seed_min[k],
                    msacRuns(scene, 4, 3, k == 0, 3, runs, seed)});
  out << seed000Table(std::string("Table 6.") + (scene_no == 1 ? "2" : "3") +
                          ": path post-processing, scene " + std::to_string(scene_no) +
                          " (MAX 3, m 4)",
                      "post-processing", cols, scene_no == 1 ? opt1 : opt2, rows);
  if (scene_no == 2)
    out << "Seed: processing shortens the average " << seed000Number(1018.16 / 149.12, 1)
        << "x; ours: " << seed000Number(cols[1].ours.mean_length / cols[0].ours.mean_length, 1)
        << "x.\n\n";
  return cols;
}

// Tables 6.4-6.7: number of ants and MAX.
std::vector<std::vector<Seed000Column>> antSweepTables(const MsacSetting& at,
                                                       std::ostringstream& out,
                                                       std::vector<JsonObject>& rows) {
  const int runs = at.runs;
  const std::uint64_t seed = at.seed;
  const Seed000Scene &free_scene = at.scenes.free_scene, &scene1 = at.scenes.scene1,
                     &scene2 = at.scenes.scene2;
  const double opt_free = at.scenes.opt_free, opt1 = at.scenes.opt1, opt2 = at.scenes.opt2;
  struct Sweep {
    const char* title;
    const Seed000Scene* scene;
    double optimum;
    int max_iterations;
    double t[3], mean[3], min[3];
  };
  const Sweep sweeps[] = {
      {"Table 6.4: number of ants, MAX 3, scene 2",
       &scene2,
       opt2,
       3,
       {2.521, 3.682, 6.167},
       {152.71, 146.95, 149.80},
       {142.41, 136.75, 138.51}},
      {"Table 6.5: number of ants, MAX 1, scene 2",
       &scene2,
       opt2,
       1,
       {0.875, 1.212, 1.937},
       {158.45, 157.02, 156.62},
       {150.49, 139.58, 148.41}},
      {"Table 6.6: number of ants, MAX 3, scene 1",
       &scene1,
       opt1,
       3,
       {0.060, 0.100, 0.206},
       {73.84, 73.84, 73.84},
       {73.84, 73.84, 73.84}},
      {"Table 6.7: number of ants, MAX 3, free scene",
       &free_scene,
       opt_free,
       3,
       {0.083, 0.145, 0.214},
       {65.05, 65.05, 65.05},
       {65.05, 65.05, 65.05}},
  };
  std::vector<std::vector<Seed000Column>> sweep_cols;
  for (const Sweep& s : sweeps) {
    std::vector<Seed000Column> cols;
    const int ms[3] = {2, 4, 8};
    for (int k = 0; k < 3; ++k)
      cols.push_back({std::to_string(ms[k]), s.t[k], s.mean[k], s.min[k],
                      msacRuns(*s.scene, ms[k], s.max_iterations, true, 3, runs, seed)});
    out << seed000Table(s.title, "m", cols, s.optimum, rows);
    sweep_cols.push_back(cols);
  }
  return sweep_cols;
}

// Claim 4 and the speed remark of §6.1.4: MAX 1, m 1. Returns scene 2's runs (for the findings).
Seed000Stats maxOneSection(const MsacSetting& at, std::ostringstream& out,
                           std::vector<JsonObject>& rows) {
  const int runs = at.runs;
  const std::uint64_t seed = at.seed;
  const Options& options = at.options;
  const Seed000Scene &scene1 = at.scenes.scene1, &scene2 = at.scenes.scene2;
  const int many = options.quick ? 10 : 10 * runs;
  const Seed000Stats s2 = msacRuns(scene2, 1, 1, true, 3, many, seed);
  const Seed000Stats s1_on = msacRuns(scene1, 1, 1, true, 3, many, seed);
  const Seed000Stats s1_off = msacRuns(scene1, 1, 1, false, 3, many, seed);
  out << "### MAX 1, m 1 (§6.1.4)\n\n| figure | seed | ours |\n|---|---|---|\n"
      << "| scene 2: runs without a path | about 30% | "
      << seed000Number(100.0 * s2.failures / s2.runs, 0) << "% of " << s2.runs << " |\n"
      << "| scene 1: avg. time with post-processing | 0.0176 s | "
      << seed000Number(s1_on.mean_ms, 3) << " ms |\n"
      << "| scene 1: avg. time without post-processing | 0.00839 s | "
      << seed000Number(s1_off.mean_ms, 3) << " ms |\n"
      << "| scene 1: avg. length with / without processing | - | "
      << seed000Number(s1_on.mean_length, 2) << " / " << seed000Number(s1_off.mean_length, 2)
      << " |\n\n";
  JsonObject row;
  row.add("table", "MAX 1, m 1 (6.1.4)")
      .add("scene2_failure_percent", 100.0 * s2.failures / s2.runs)
      .add("seed_scene2_failure_percent", 30.0)
      .add("scene1_time_ms_with_processing", s1_on.mean_ms)
      .add("seed_scene1_time_s_with_processing", 0.0176)
      .add("scene1_time_ms_without_processing", s1_off.mean_ms)
      .add("seed_scene1_time_s_without_processing", 0.00839);
  rows.push_back(row);
  return s2;
}

}  // namespace

Report seed000Msac(const Options& options) {
  const int runs = seed000RunCount(options);
  const std::uint64_t seed = options.seed;
  const Seed000SceneSet scenes = seed000Scenes();
  std::ostringstream out;
  std::vector<JsonObject> rows;
  out << seed000Preamble("Seed 000: MSAC (Multi-Scout Ants Cooperation)", scenes, runs, seed,
                         "unconditional diagonals, S_max = 1250; an iteration ends when the "
                         "two groups meet (§4.3; the last tables compare the literal step 6). "
                         "Our MSAC stops early when its "
                         "path equals the obstacle-free octile distance (nothing can be "
                         "shorter); the seed's always ran MAX iterations.");
  const MsacSetting at{options, runs, seed, scenes};
  const std::vector<Seed000Column> tabu_cols = tabuTable(at, out, rows);
  std::vector<Seed000Column> post_cols[2];
  for (int scene_no : {1, 2})
    post_cols[scene_no - 1] = postProcessingTable(at, scene_no, out, rows);
  const std::vector<std::vector<Seed000Column>> sweep_cols = antSweepTables(at, out, rows);
  const Seed000Stats s2 = maxOneSection(at, out, rows);
  const IterationEndResults ends = iterationEndSection(at, out, rows);
  const Scene3Results scene3 = scene3Section(at, out, rows);
  MsacResults results{tabu_cols, post_cols[0], post_cols[1], sweep_cols, s2, ends, scene3};
  out << msacMaps(options, scenes, results) << agreementSection(msacFindings(results, scenes));
  return {out.str(), rows};
}

}  // namespace cosim::reproduce
