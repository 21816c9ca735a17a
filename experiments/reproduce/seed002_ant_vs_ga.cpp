// Reproduction of seed 002, part A (summary section 3.1): the grid ant algorithm against the
// genetic algorithm on a relatively simple, a relatively complex and a complex workspace, from
// three start points to three targets, path length and time, beside the seed's numbers.
// The seed shows its workspaces only as (missing) figures: ours are reconstructions, 500 cm x
// 500 cm at 5 cm per cell (100 x 100 cells; the seed's coordinates run to 465), with 4, 8 and 14
// rectangular obstacles; the start and target points are the seed's, in cm. Absolute lengths
// therefore differ; the comparable figures are ant vs GA and both vs the optimum (A*).
// The seed does not define the unit of its heuristic h ("difference of angle"); on these maps
// (2 runs) the ants' mean gap to the optimum was 100-250% with h = 1 + (turn + deviation from
// the goal direction) / 45 degrees, 65-135% with the same in degrees, 11-29% with both squared,
// and 3-15% with ant_grid's h = 1 + deviation^2 + turn (degrees), which we use.
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "experiments/cli/output_files.h"
#include "experiments/reproduce/reproduction.h"
#include "planning/grid/astar.h"
#include "planning/swarm/ant_grid.h"
#include "planning/swarm/genetic_algorithm.h"

namespace cosim::reproduce {

namespace {

constexpr double kCellCm = 5.0;

struct Rect {
  int x0, y0, x1, y1;  // inclusive cell ranges
};

struct Workspace {
  const char* name;
  std::vector<Rect> obstacles;
  int ants, ant_iterations;                // the seed's convergence table (ACO columns)
  int population, generations;             // (GA columns)
  double seed_time_ant_s, seed_time_ga_s;  // the seed's time table
};

struct SeedQuery {
  int sx, sy, tx, ty;  // cm
};

const SeedQuery kQueries[] = {{5, 50, 400, 450}, {20, 55, 460, 455}, {30, 65, 465, 460}};
// Seed's path lengths (cm): [workspace][query] = {ant, genetic}.
const double kSeedLength[3][3][2] = {{{610.34, 618.05}, {655.72, 659.69}, {648.62, 652.08}},
                                     {{919.45, 923.04}, {711.28, 719.48}, {697.80, 707.09}},
                                     {{913.82, 921.03}, {718.59, 722.28}, {698.51, 703.79}}};

std::vector<Workspace> workspaces() {
  const std::vector<Rect> simple = {
      {20, 20, 35, 40}, {50, 8, 60, 45}, {28, 58, 55, 72}, {68, 48, 84, 68}};
  std::vector<Rect> medium = simple;
  for (const Rect& r :
       std::vector<Rect>{{8, 30, 14, 55}, {38, 82, 74, 87}, {66, 22, 92, 30}, {84, 74, 90, 86}})
    medium.push_back(r);
  std::vector<Rect> complex = medium;
  for (const Rect& r : std::vector<Rect>{{0, 64, 20, 67},
                                         {40, 42, 47, 56},
                                         {60, 76, 64, 99},
                                         {88, 40, 99, 44},
                                         {20, 88, 30, 99},
                                         {72, 0, 76, 16}})
    complex.push_back(r);
  return {{"relatively simple", simple, 20, 30, 20, 50, 47.721, 1522.03},
          {"relatively complex", medium, 25, 45, 35, 80, 648.69, 1865.28},
          {"complex", complex, 30, 50, 50, 100, 972.65, 2560.42}};
}

OccupancyGrid gridOf(const Workspace& w) {
  OccupancyGrid g(100, 100, 1, kCellCm / 100.0);
  for (const Rect& r : w.obstacles)
    for (int y = r.y0; y <= r.y1; ++y)
      for (int x = r.x0; x <= r.x1; ++x) g.setBlocked(x, y, 0, true);
  return g;
}

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

std::string point(int x, int y) {
  char b[32];
  std::snprintf(b, sizeof b, "(%d,%d)", x, y);
  return b;
}

struct Stats {
  double best = 1e300, sum = 0.0, time_ms = 0.0;
  int ok = 0, runs = 0;
  double mean() const { return ok ? sum / ok : 0.0; }
};

}  // namespace

std::string seed002AntVsGa(const Options& options) {
  const int runs = options.runs > 0 ? options.runs : (options.quick ? 2 : 10);
  std::ostringstream md, csv;
  md << "# Seed 002, part A: grid ant algorithm vs genetic algorithm\n\n"
     << "Workspaces reconstructed (the seed's figures are missing): 100 x 100 cells of 5 cm, "
        "rectangular obstacles (4 / 8 / 14), start and target points of the seed (cm; cell = "
        "coordinate / 5). Ant: `ant_grid` with the seed's defaults (alpha 1, beta 0.5, "
        "evaporation 0.1, deposit 0.5, initial pheromone 0.5, 8 directions) and the seed's ants / "
        "iterations per workspace; GA: `ga` with the seed's population / iterations per "
        "workspace (pc 0.6, pm 0.05). "
     << runs << " runs per cell of the table (seeds " << options.seed << ".."
     << options.seed + runs - 1
     << "); lengths in cm (mean and best over runs); optimum = A* (8 directions, no corner "
        "cutting) on the same grid.\n\n"
     << "| workspace | start | target | seed ant | seed GA | our ant mean (best) | our GA mean "
        "(best) | A* optimum | ant gap | GA gap |\n|---|---|---|---|---|---|---|---|---|---|\n";
  csv << "workspace,start,target,planner,runs,successes,mean_length_cm,best_length_cm,"
         "mean_time_ms,optimal_cm,seed_length_cm\n";
  std::ostringstream times;
  times << "\n| workspace | ants / iterations | GA population / generations | seed time ant (s) | "
           "seed time GA (s) | seed GA/ant | our time ant (ms) | our time GA (ms) | our GA/ant |\n"
           "|---|---|---|---|---|---|---|---|---|\n";
  const auto ws = workspaces();
  for (std::size_t wi = 0; wi < ws.size(); ++wi) {
    const Workspace& w = ws[wi];
    const OccupancyGrid grid = gridOf(w);
    AntGridParams ap;
    ap.ants = w.ants;
    ap.iterations = w.ant_iterations;
    GeneticAlgorithmParams gp;
    gp.population = w.population;
    gp.generations = w.generations;
    double ant_time = 0.0, ga_time = 0.0;
    for (int qi = 0; qi < 3; ++qi) {
      const SeedQuery& sq = kQueries[qi];
      const Cell s{static_cast<int>(sq.sx / kCellCm), static_cast<int>(sq.sy / kCellCm), 0};
      const Cell t{static_cast<int>(sq.tx / kCellCm), static_cast<int>(sq.ty / kCellCm), 0};
      const GridPlanResult opt = planAStar(grid, s, t);
      const double optimum = opt.success ? opt.length * kCellCm : 0.0;
      Stats st[2];
      for (int r = 0; r < runs; ++r) {
        GridQuery q;
        q.grid = &grid;
        q.start = s;
        q.goal = t;
        q.seed = options.seed + r;
        q.time_limit_s = 60.0;
        AntGrid ant(ap);
        GeneticAlgorithm ga(gp);
        const GridPlanResult results[2] = {ant.solveGrid(q), ga.solveGrid(q)};
        for (int k = 0; k < 2; ++k) {
          ++st[k].runs;
          st[k].time_ms += results[k].time_ms;
          if (!results[k].success) continue;
          ++st[k].ok;
          st[k].sum += results[k].length * kCellCm;
          st[k].best = std::min(st[k].best, results[k].length * kCellCm);
        }
      }
      ant_time += st[0].time_ms / runs;
      ga_time += st[1].time_ms / runs;
      const std::string sp = point(sq.sx, sq.sy), tp = point(sq.tx, sq.ty);
      md << "| " << w.name << " | " << sp << " | " << tp << " | "
         << fmt("%.2f", kSeedLength[wi][qi][0]) << " | " << fmt("%.2f", kSeedLength[wi][qi][1])
         << " | " << fmt("%.1f", st[0].mean()) << " (" << fmt("%.1f", st[0].best) << ") | "
         << fmt("%.1f", st[1].mean()) << " (" << fmt("%.1f", st[1].best) << ") | "
         << fmt("%.1f", optimum) << " | " << fmt("%.1f%%", 100 * (st[0].mean() / optimum - 1))
         << " | " << fmt("%.1f%%", 100 * (st[1].mean() / optimum - 1)) << " |\n";
      for (int k = 0; k < 2; ++k)
        csv << "\"" << w.name << "\",\"" << sp << "\",\"" << tp << "\","
            << (k == 0 ? "ant_grid" : "ga") << "," << st[k].runs << "," << st[k].ok << ","
            << st[k].mean() << "," << st[k].best << "," << st[k].time_ms / st[k].runs << ","
            << optimum << "," << kSeedLength[wi][qi][k] << "\n";
    }
    times << "| " << w.name << " | " << w.ants << " / " << w.ant_iterations << " | " << w.population
          << " / " << w.generations << " | " << w.seed_time_ant_s << " | " << w.seed_time_ga_s
          << " | " << fmt("%.1f", w.seed_time_ga_s / w.seed_time_ant_s) << " | "
          << fmt("%.1f", ant_time / 3) << " | " << fmt("%.1f", ga_time / 3) << " | "
          << fmt("%.2f", ga_time / ant_time) << " |\n";
  }
  md << "\nPath-construction time (seed: MATLAB R2011, seconds, per workspace; ours: mean ms per "
        "query on this machine):\n"
     << times.str();
  if (!options.out_dir.empty())
    writeFileAtomically(std::filesystem::path(options.out_dir) / "seed002-ant-vs-ga.csv",
                        csv.str());
  return md.str();
}

}  // namespace cosim::reproduce
