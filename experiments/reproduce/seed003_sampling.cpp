// Reproduction of seed 003's continuous-space comparison (Navratil 2019, sec. 4.1.2, Tables 4-17):
// RRT, RRT* and RRT*FN with four tree caps, on its 2D map (modes 1 and 2) and its three 3D maps
// (parameter sets 1-4), mean path length and time over many runs, beside the thesis's numbers.
// The maps are the reconstructions of planning/worlds/seed003_maps (the thesis shows its layouts
// only as figures), so absolute lengths differ; the ratios to RRT* are the comparable figures.
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "experiments/cli/output_files.h"
#include "experiments/reproduce/reproduction.h"
#include "planning/planner_registry.h"
#include "planning/worlds/seed003_maps.h"

namespace cosim::reproduce {

namespace {

// One table of the thesis: a map, a mode, N, step, rewire radius, four RRT*FN caps, and the
// published mean length [m] and time [s] for RRT, RRT*, FN cap 1..4 (in that order).
struct SeedTable {
  const char* label;  // e.g. "Tab. 6"
  const char* map;    // Seed003Map::name
  const char* set;    // "mode 1" or "set 1".."set 4"
  int mode, max_nodes;
  double step, radius;
  int caps[4];
  double length[6];
  double time_s[6];
};

// Values copied from the thesis (summary section 3.4); times are MATLAB seconds on an i5-9600K.
const SeedTable kTables[] = {
    {"Tab. 4",
     "2d",
     "mode 1",
     1,
     1000,
     1,
     3,
     {200, 250, 350, 500},
     {43.1433, 37.1015, 36.9609, 36.5054, 35.9965, 36.4896},
     {1.4430, 2.9678, 2.7561, 2.8569, 3.1148, 3.5057}},
    {"Tab. 5",
     "2d",
     "mode 2",
     2,
     1000,
     1,
     3,
     {200, 250, 350, 500},
     {43.1846, 37.2061, 36.1307, 36.2358, 35.9978, 36.6239},
     {2.4456, 4.9230, 3.7790, 4.2684, 5.9635, 6.5718}},
    {"Tab. 6",
     "3d-1",
     "set 1",
     1,
     2000,
     2,
     4,
     {400, 500, 700, 1000},
     {55.6559, 52.1007, 52.8687, 52.7695, 50.9060, 50.5184},
     {0.9092, 1.4644, 1.2559, 1.3827, 1.4756, 1.5267}},
    {"Tab. 7",
     "3d-1",
     "set 2",
     1,
     2000,
     4,
     6,
     {400, 500, 700, 1000},
     {45.5008, 38.9544, 43.2325, 38.9811, 39.4231, 38.0564},
     {0.2645, 0.4563, 0.3743, 0.3677, 0.3675, 0.4692}},
    {"Tab. 8",
     "3d-1",
     "set 3",
     2,
     2000,
     2,
     4,
     {400, 500, 700, 1000},
     {57.3988, 46.1881, 51.2760, 52.7098, 49.1245, 51.4127},
     {5.9156, 9.2906, 7.7363, 8.8308, 11.1993, 10.5190}},
    {"Tab. 9",
     "3d-1",
     "set 4",
     2,
     2000,
     4,
     6,
     {400, 500, 700, 1000},
     {63.2382, 49.9547, 46.9837, 48.0143, 46.8475, 45.2460},
     {5.9595, 11.2049, 11.3855, 13.4410, 15.2311, 15.9961}},
    {"Tab. 10",
     "3d-2",
     "set 1",
     1,
     2000,
     2,
     4,
     {400, 500, 700, 1000},
     {59.5080, 45.8919, 51.4798, 49.9848, 48.6896, 47.2185},
     {3.6096, 12.0180, 4.9627, 6.7831, 11.4335, 12.0438}},
    {"Tab. 11",
     "3d-2",
     "set 2",
     1,
     2000,
     4,
     6,
     {400, 500, 700, 1000},
     {62.5122, 50.4312, 48.2073, 46.6169, 48.8110, 45.6808},
     {0.9015, 3.9275, 2.5689, 3.8569, 7.0857, 12.8702}},
    {"Tab. 12",
     "3d-2",
     "set 3",
     2,
     2000,
     2,
     4,
     {400, 500, 700, 1000},
     {61.4200, 48.9517, 49.2039, 46.7572, 44.4831, 51.2812},
     {9.6523, 16.2500, 11.6952, 13.0641, 16.5327, 19.7568}},
    {"Tab. 13",
     "3d-2",
     "set 4",
     2,
     2000,
     4,
     6,
     {400, 500, 700, 1000},
     {60.3361, 45.0949, 46.6022, 46.8474, 42.3405, 46.1419},
     {10.1621, 38.6884, 21.4849, 19.3696, 24.9164, 29.3715}},
    {"Tab. 14",
     "3d-3",
     "set 1",
     1,
     2000,
     2,
     4,
     {400, 500, 700, 1000},
     {118.6797, 105.3060, 107.3563, 110.8363, 109.3914, 110.1904},
     {4.2010, 7.7727, 5.9929, 6.5799, 5.9473, 4.9213}},
    {"Tab. 15",
     "3d-3",
     "set 2",
     1,
     2000,
     4,
     6,
     {400, 500, 700, 1000},
     {115.9104, 103.9626, 102.6060, 104.9756, 105.5307, 108.3151},
     {0.8259, 1.8121, 2.2536, 1.6624, 1.8859, 1.8622}},
    {"Tab. 16",
     "3d-3",
     "set 3",
     2,
     2000,
     2,
     4,
     {400, 500, 700, 1000},
     {117.0083, 98.6030, 106.7099, 105.6800, 111.3333, 107.8640},
     {6.7008, 10.6041, 7.8659, 8.2446, 10.9909, 10.5702}},
    {"Tab. 17",
     "3d-3",
     "set 4",
     2,
     2000,
     4,
     6,
     {400, 500, 700, 1000},
     {118.8788, 106.7668, 99.7307, 107.4164, 105.3917, 103.6720},
     {6.2319, 11.7566, 9.1322, 10.0937, 11.8910, 11.5870}},
};

struct Stats {
  int runs = 0, successes = 0;
  double length_sum = 0, time_ms_sum = 0, nodes_sum = 0;
  double meanLength() const { return successes ? length_sum / successes : 0.0; }
  double meanTimeMs() const { return runs ? time_ms_sum / runs : 0.0; }
};

// Runs one column of a table (`planner` with the table's parameters; cap > 0 for RRT*FN).
Stats runColumn(const SeedTable& t, const Seed003Map& map, const std::string& planner, int cap,
                const Options& options, int runs) {
  Stats s;
  for (int i = 0; i < runs; ++i) {
    ParamSet p("seed003-sampling");
    p.set("mode", std::to_string(t.mode));
    p.set("max_nodes", std::to_string(t.max_nodes));
    p.set("step", std::to_string(t.step));
    // The thesis does not say it biased sampling towards the goal; a node within one step of
    // the goal connects to it (the thesis leaves "goal reached" undefined).
    p.set("goal_bias", "0");
    if (planner != "rrt") p.set("rewire_radius", std::to_string(t.radius));
    if (cap > 0) p.set("max_tree_nodes", std::to_string(cap));
    auto solver = makePlanner(planner, p, "seed003-sampling");
    PlanningProblem prob;
    prob.world = &map.world;
    prob.start = map.start;
    prob.goal = map.goal;
    prob.inflation = 0.0;  // the thesis planned for a point mass
    prob.planar = map.planar;
    prob.time_limit_s = 60.0;
    prob.seed = options.seed + static_cast<std::uint64_t>(i);
    const PlanResult r = solver->solve(prob);
    ++s.runs;
    s.time_ms_sum += r.time_ms;
    s.nodes_sum += r.counters.count("nodes") ? r.counters.at("nodes") : 0.0;
    if (r.success) {
      ++s.successes;
      s.length_sum += r.path.length();
    }
  }
  return s;
}

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace

std::string seed003Sampling(const Options& options) {
  const int runs = options.runs > 0 ? options.runs : (options.quick ? 3 : 100);
  const std::vector<Seed003Map> maps = seed003Maps();
  std::ostringstream md, csv;
  md << "# Seed 003, continuous planners: RRT, RRT*, RRT*FN (Tables 4-17)\n\n"
     << "Runs per column: " << runs << " (the thesis: 1000), seeds " << options.seed << ".."
     << options.seed + runs - 1
     << ". Lengths are means over successful runs; times are means over all runs, in ms here "
        "(C++, one core) and in s in the thesis (MATLAB). **The maps are reconstructions** "
        "(planning/worlds/seed003_maps: the thesis shows its obstacle layouts only as figures), "
        "so compare the ratios to RRT* (the `% of RRT*` columns), not absolute lengths. "
        "Point-mass planning (no inflation) and no goal bias, as in the thesis; a node within "
        "one step of the goal connects to it.\n\n";
  for (const Seed003Map& m : maps) md << "- map `" << m.name << "`: " << m.description << "\n";
  csv << "table,map,set,planner,cap,runs,successes,mean_length_m,mean_time_ms,mean_nodes,"
         "seed_length_m,seed_time_s\n";

  for (const SeedTable& t : kTables) {
    if (options.quick && std::string(t.label) != "Tab. 4" && std::string(t.label) != "Tab. 6")
      continue;
    const Seed003Map* map = nullptr;
    for (const auto& m : maps)
      if (m.name == t.map) map = &m;
    if (!map) continue;
    md << "\n## " << t.label << ": map " << t.map << ", " << t.set << " (mode " << t.mode
       << ", N = " << t.max_nodes << ", step " << t.step << " m, radius " << t.radius << " m)\n\n"
       << "| planner | success | length [m] | % of RRT* | time [ms] | seed length [m] | seed % of "
          "RRT* | seed time [s] |\n|---|---|---|---|---|---|---|---|\n";
    std::vector<std::pair<std::string, int>> columns = {{"rrt", 0}, {"rrt_star", 0}};
    for (int cap : t.caps) columns.emplace_back("rrt_star_fn", cap);
    std::vector<Stats> stats;
    for (const auto& [planner, cap] : columns)
      stats.push_back(runColumn(t, *map, planner, cap, options, runs));
    const double ours_ref = stats[1].meanLength(), seed_ref = t.length[1];
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const Stats& s = stats[c];
      const std::string label = columns[c].second > 0
                                    ? "RRT*FN " + std::to_string(columns[c].second)
                                    : (c == 0 ? "RRT" : "RRT*");
      md << "| " << label << " | " << s.successes << "/" << s.runs << " | "
         << fmt("%.2f", s.meanLength()) << " | "
         << fmt("%.1f %%", ours_ref > 0 ? 100.0 * s.meanLength() / ours_ref : 0.0) << " | "
         << fmt("%.2f", s.meanTimeMs()) << " | " << fmt("%.2f", t.length[c]) << " | "
         << fmt("%.1f %%", 100.0 * t.length[c] / seed_ref) << " | " << fmt("%.3f", t.time_s[c])
         << " |\n";
      csv << t.label << "," << t.map << "," << csvField(t.set) << "," << columns[c].first << ","
          << columns[c].second << "," << s.runs << "," << s.successes << ","
          << fmt("%.4f", s.meanLength()) << "," << fmt("%.4f", s.meanTimeMs()) << ","
          << fmt("%.1f", s.runs ? s.nodes_sum / s.runs : 0.0) << "," << t.length[c] << ","
          << t.time_s[c] << "\n";
    }
  }
  if (!options.out_dir.empty())
    writeFileAtomically(std::filesystem::path(options.out_dir) / "seed003-sampling.csv", csv.str());
  return md.str();
}

}  // namespace cosim::reproduce
