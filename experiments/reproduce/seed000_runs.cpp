#include "experiments/reproduce/seed000_runs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "experiments/reproduce/reproduction_map.h"
#include "planning/grid/astar.h"

namespace cosim::reproduce {

namespace {
constexpr int kTimingRepeats = 9;
constexpr double kTimingBudgetMs = 20.0;
constexpr int kMinRepeats = 3;
constexpr double kRepeatBelowMs = 100.0;
}  // namespace

Seed000Stats runSeed000(GridPlanner& planner, const Seed000Scene& scene, int runs,
                        std::uint64_t seed, double time_limit_s) {
  Seed000Stats s;
  s.runs = runs;
  s.min_length = std::numeric_limits<double>::infinity();
  double time_sum = 0.0, length_sum = 0.0, length_sq = 0.0;
  for (int i = 0; i < runs; ++i) {
    GridQuery q;
    q.grid = &scene.grid;
    q.start = scene.start;
    q.goal = scene.goal;
    q.seed = seed + static_cast<std::uint64_t>(i);
    q.time_limit_s = time_limit_s;
    const GridPlanResult r = planner.solveGrid(q, StopToken::untimed());
    // A search of a tenth of a millisecond is timed below the noise of a shared machine (one
    // preempted run can weigh more than the other nine): repeat a search of under 100 ms (same
    // seed, same search) at least 3 times and on until 20 ms have passed, at most 9 times, and
    // count its fastest repeat.
    double fastest = r.time_ms, spent = r.time_ms;
    for (int k = 1; k < kTimingRepeats && r.time_ms < kRepeatBelowMs &&
                    (k < kMinRepeats || spent < kTimingBudgetMs);
         ++k) {
      const double t = planner.solveGrid(q, StopToken::untimed()).time_ms;
      fastest = std::min(fastest, t);
      spent += t;
    }
    time_sum += fastest;
    if (r.counters.count("steps")) s.mean_steps += r.counters.at("steps") / runs;
    if (!r.success) {
      ++s.failures;
      continue;
    }
    length_sum += r.length;
    length_sq += r.length * r.length;
    if (r.length < s.min_length) s.best_path = r.cells;
    s.min_length = std::min(s.min_length, r.length);
  }
  const int ok = runs - s.failures;
  s.mean_ms = runs > 0 ? time_sum / runs : 0.0;
  s.mean_length = ok > 0 ? length_sum / ok : std::nan("");
  if (ok == 0) s.min_length = std::nan("");
  if (ok > 1)
    s.sd_length = std::sqrt(std::max(0.0, (length_sq - length_sum * length_sum / ok) / (ok - 1)));
  return s;
}

std::string seed000Number(double v, int decimals) {
  if (std::isnan(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string seed000Table(const std::string& title, const std::string& swept,
                         const std::vector<Seed000Column>& columns, double optimum,
                         std::vector<JsonObject>& rows) {
  for (const Seed000Column& c : columns) {
    JsonObject row;
    row.add("table", title)
        .add(swept, c.label)
        .add("optimum", optimum)
        .add("seed_time_s", c.seed_time_s)
        .add("seed_mean_length", c.seed_mean)
        .add("seed_min_length", c.seed_min)
        .add("runs", c.ours.runs)
        .add("failures", c.ours.failures)
        .add("mean_time_ms", c.ours.mean_ms)
        .add("mean_length", c.ours.mean_length)
        .add("min_length", c.ours.min_length);
    rows.push_back(row);
  }
  std::ostringstream out;
  out << "### " << title << "\n\nOptimum of our scene (A*): " << seed000Number(optimum, 2)
      << ". Seed: MATLAB on an i3 330M; ours: C++, this machine.\n\n| " << swept << " |";
  for (const auto& c : columns) out << " " << c.label << " |";
  out << "\n|---|";
  for (std::size_t i = 0; i < columns.size(); ++i) out << "---|";
  out << "\n";
  auto row = [&](const char* name, auto value) {
    out << "| " << name << " |";
    for (const auto& c : columns) out << " " << value(c) << " |";
    out << "\n";
  };
  row("avg. time, seed [s]",
      [](const Seed000Column& c) { return seed000Number(c.seed_time_s, 3); });
  row("avg. time, ours [ms]",
      [](const Seed000Column& c) { return seed000Number(c.ours.mean_ms, 3); });
  row("avg. length, seed", [](const Seed000Column& c) { return seed000Number(c.seed_mean, 2); });
  row("avg. length, ours",
      [](const Seed000Column& c) { return seed000Number(c.ours.mean_length, 2); });
  row("min. length, seed", [](const Seed000Column& c) { return seed000Number(c.seed_min, 2); });
  row("min. length, ours",
      [](const Seed000Column& c) { return seed000Number(c.ours.min_length, 2); });
  row("runs without a path, ours", [](const Seed000Column& c) {
    return std::to_string(c.ours.failures) + "/" + std::to_string(c.ours.runs);
  });
  out << "\n";
  return out.str();
}

Seed000SceneSet seed000Scenes() {
  Seed000SceneSet s{seed000FreeScene(), seed000Scene1(), seed000Scene2(), 0.0, 0.0, 0.0};
  s.opt_free = seed000Optimum(s.free_scene, false);
  s.opt1 = seed000Optimum(s.scene1, false);
  s.opt2 = seed000Optimum(s.scene2, false);
  return s;
}

int seed000RunCount(const Options& options) {
  return options.runs > 0 ? options.runs : (options.quick ? 2 : 10);
}

std::string seed000Preamble(const std::string& title, const Seed000SceneSet& scenes, int runs,
                            std::uint64_t seed, const std::string& settings) {
  std::ostringstream out;
  out << "# " << title << "\n\nScenes: ";
  for (const Seed000Scene* s : {&scenes.free_scene, &scenes.scene1, &scenes.scene2})
    out << s->name << " (" << s->origin << ")" << (s == &scenes.scene2 ? ".\n" : "; ");
  out << runs << " runs per setting (seeds " << seed << "..." << seed + runs - 1 << "); "
      << settings
      << " A run of under 100 ms is timed as the fastest of 3 to 9 repeats (the same seed repeats "
         "the same search; repeats stop after 20 ms): searches of a tenth of a millisecond are "
         "otherwise timed below the noise of a shared machine.\n\n";
  const double opt2 = seed000Optimum(scenes.scene2, false);
  out << "Scene 2's optimum (" << seed000Number(opt2, 2)
      << ") lies below every path the seed reports there: its best ever, 132.41, is "
      << seed000Number(100.0 * (132.41 / opt2 - 1.0), 0)
      << " % above it. The seed gives no optimum for scene 2, and its methods do not reach the "
         "optimum where there are local minima: its SACOdm stayed 16-35 % above the optimum on "
         "the two scenes where the optimum is known (85.74 vs 73.84 on scene 1, 87.88 vs 65.05 "
         "on the free scene). So scene 2 was rebuilt to give the seed's lengths (see its "
         "description), not to put its optimum just below 132.41.\n\n";
  return out.str();
}

std::string drawSeed000Scene(const Options& options, const std::string& name, int index,
                             const Seed000Scene& scene,
                             const std::vector<std::pair<std::string, std::vector<Cell>>>& paths) {
  ReproductionMap fig = gridMap(scene.name, scene.grid, scene.start, scene.goal);
  for (const auto& [label, cells] : paths)
    if (!cells.empty()) fig.paths.push_back({label, cellCentres(cells)});
  return writeReproductionMap(options.out_dir, name, index, fig);
}

double seed000Optimum(const Seed000Scene& scene, bool conditional_diagonal) {
  return planAStar(scene.grid, scene.start, scene.goal, GridMoves{8, !conditional_diagonal}).length;
}

}  // namespace cosim::reproduce
