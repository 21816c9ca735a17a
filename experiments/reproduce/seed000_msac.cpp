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

Seed000Stats msacRuns(const Seed000Scene& scene, int m, int max_iterations, bool post_processing,
                      int tabu_version, int runs, std::uint64_t seed) {
  MsacParams p;
  p.ants = m;
  p.iterations = max_iterations;
  p.s_max = 1250;
  p.post_processing = post_processing;
  p.tabu_version = tabu_version;
  p.conditional_diagonal = false;
  Msac msac(p);
  return runSeed000(msac, scene, runs, seed);
}

// What every table of this reproduction runs on: the scenes, their optima, the runs and seed.
struct MsacSetting {
  const Options& options;
  int runs;
  std::uint64_t seed;
  const Seed000SceneSet& scenes;
};

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
                         "unconditional diagonals, S_max = 1250. Our MSAC stops early when its "
                         "path equals the obstacle-free octile distance (nothing can be "
                         "shorter); the seed's always ran MAX iterations.");
  const MsacSetting at{options, runs, seed, scenes};
  const std::vector<Seed000Column> tabu_cols = tabuTable(at, out, rows);
  std::vector<Seed000Column> post_cols[2];
  for (int scene_no : {1, 2})
    post_cols[scene_no - 1] = postProcessingTable(at, scene_no, out, rows);
  const std::vector<std::vector<Seed000Column>> sweep_cols = antSweepTables(at, out, rows);
  const Seed000Stats s2 = maxOneSection(at, out, rows);
  MsacResults results{tabu_cols, post_cols[0], post_cols[1], sweep_cols, s2};
  out << msacMaps(options, scenes, results) << agreementSection(msacFindings(results, scenes));
  return {out.str(), rows};
}

}  // namespace cosim::reproduce
