#pragma once
// Repeated runs of one planner on one seed-000 scene, summarised as the seed's tables are
// (average time, average and minimum length over the runs), plus the failures the seed mentions
// in passing ("one run found no path and was excluded").
#include <string>
#include <vector>

#include "core/json_writer.h"
#include "experiments/reproduce/reproduction.h"
#include "experiments/reproduce/seed000_scenes.h"
#include "planning/grid/grid_planner.h"

namespace cosim::reproduce {

struct Seed000Stats {
  int runs = 0, failures = 0;
  double mean_ms = 0.0, mean_length = 0.0, min_length = 0.0;
  double sd_length = 0.0;       // sample standard deviation of the successful runs' lengths
  double mean_steps = 0.0;      // the planner's "steps" counter (MSAC: synchronised steps), mean
  std::vector<Cell> best_path;  // the shortest path found (for the map figures)
};

// Run i uses seed options.seed + i.
Seed000Stats runSeed000(GridPlanner& planner, const Seed000Scene& scene, int runs,
                        std::uint64_t seed, double time_limit_s = 60.0);

// One column of a seed table: the seed's figures (NaN where it gives none) and ours.
struct Seed000Column {
  std::string label;
  double seed_time_s, seed_mean, seed_min;
  Seed000Stats ours;
};

// A markdown table in the seed's layout (rows: average time, average length, minimum length),
// seed and ours on alternate rows, with the scene's optimum under the title. Each column is
// also appended to `rows` (NAME.json) as {table, swept, value, optimum, seed_* and our figures}.
std::string seed000Table(const std::string& title, const std::string& swept,
                         const std::vector<Seed000Column>& columns, double optimum,
                         std::vector<JsonObject>& rows);

// The three scenes of the MSAC and SACOdm tables with their optima (unconditional diagonals).
struct Seed000SceneSet {
  Seed000Scene free_scene, scene1, scene2;
  double opt_free, opt1, opt2;
};
Seed000SceneSet seed000Scenes();

// Runs per setting: --runs, else the seed's 10 (2 with --quick).
int seed000RunCount(const Options& options);

// The report's title and the paragraph naming the scenes, the runs and the common settings.
std::string seed000Preamble(const std::string& title, const Seed000SceneSet& scenes, int runs,
                            std::uint64_t seed, const std::string& settings);

// "12.3" with the given decimals; "-" for a NaN (no successful run).
std::string seed000Number(double v, int decimals);

// Draws `scene` with labelled paths (cells) as NAME_map<index>.png/.svg in options.out_dir;
// returns the file base (for mapFiguresMarkdown, with scene.origin as how it was rebuilt).
std::string drawSeed000Scene(const Options& options, const std::string& name, int index,
                             const Seed000Scene& scene,
                             const std::vector<std::pair<std::string, std::vector<Cell>>>& paths);

// The optimum of a scene for the given diagonal mode (A*).
double seed000Optimum(const Seed000Scene& scene, bool conditional_diagonal);

}  // namespace cosim::reproduce
