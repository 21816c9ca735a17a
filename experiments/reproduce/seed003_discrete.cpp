// cosim reproduce seed003-discrete: seed 003's discrete comparison (Navratil 2019, section 4.1.1,
// Tabs. 1-4): A*, Basic Theta* and Lazy Theta* on its 2D map (8-connected) and three 3D maps
// (26-connected), path length, time and line-of-sight checks, with Basic Theta* = 100%. The
// thesis's obstacle layouts exist only as figures; planning/worlds/seed003_maps.cpp rebuilds
// equivalent ones from the stated sizes, starts, goals and descriptions.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "experiments/reproduce/report_files.h"
#include "experiments/reproduce/reproduction.h"
#include "planning/grid/astar.h"
#include "planning/grid/basic_theta_star.h"
#include "planning/grid/lazy_theta_star.h"
#include "planning/worlds/seed003_maps.h"

namespace cosim::reproduce {

namespace {

// Seed 003, Tabs. 1-4: length [m], time [s], line-of-sight checks (-1: not reported), in the
// order A*, Basic Theta*, Lazy Theta*.
struct PublishedRow {
  double length[3];
  double time_s[3];
  double los[3];
};
const PublishedRow kPublished[4] = {
    {{34.7990, 33.6927, 34.0968}, {0.0420, 0.0716, 0.0674}, {-1, 653, 278}},
    {{35.5563, 35.0471, 36.0436}, {0.5531, 0.5899, 0.5604}, {-1, 12323, 1201}},
    {{37.9706, 35.7801, 35.8525}, {0.8372, 0.8510, 0.8699}, {-1, 20700, 2094}},
    {{88.4264, 81.0454, 82.1357}, {2.9822, 2.7280, 3.2075}, {-1, 41108, 4054}},
};
const char* kTableNames[4] = {"Tab. 1 (2D map)", "Tab. 2 (3D map 1)", "Tab. 3 (3D map 2)",
                              "Tab. 4 (3D map 3)"};

struct Measured {
  bool success = false;
  double length = 0, time_ms = 0, los = 0, expansions = 0;
  std::vector<double> times_ms;
};

std::string obstacleList(const World& w) {
  std::string s;
  for (const Obstacle& o : w.obstacles) {
    const Eigen::Vector3d lo = o.pos - o.size / 2, hi = o.pos + o.size / 2;
    char buf[160];
    std::snprintf(buf, sizeof buf, "[%g,%g)x[%g,%g)x[%g,%g) ", lo.x(), hi.x(), lo.y(), hi.y(),
                  lo.z(), hi.z());
    s += buf;
  }
  return s;
}

}  // namespace

Report seed003Discrete(const Options& options) {
  const int runs = options.runs > 0 ? options.runs : (options.quick ? 3 : 100);
  std::string md = "# Seed 003, discrete planners: A* vs Basic Theta* vs Lazy Theta*\n\n";
  md +=
      "Seed 003 (Navratil 2019) Tabs. 1-4 beside this program's planners on reconstructed maps. "
      "8-connected in 2D, 26-connected in 3D, no corner cutting, supercover line of sight; "
      "1 m cells; times are the median wall time of " +
      std::to_string(runs) +
      " runs per planner (the thesis: 1000 runs in MATLAB on an i5-9600K, so only the ratios "
      "compare). Percentages are relative to Basic Theta* as in the thesis.\n\n"
      "**The maps are reconstructions.** The thesis gives only sizes, obstacle counts, starts "
      "and goals; its layouts are figures. The boxes below (cells [x0,x1)x[y0,y1)x[z0,z1), "
      "metres) were chosen to match each description and to give path lengths of the "
      "published order, so lengths and check counts can be compared in kind, not digit by "
      "digit.\n\n"
      "**Seed percentages.** The thesis prints a percentage beside each value; the seed columns "
      "here show percentages recomputed from its absolute values (marked \"recomputed\"), which "
      "agree with the printed ones in all four tables to their two decimals.\n\n"
      "**Why our time ratios differ (A* takes a small fraction of Basic Theta*'s time here, "
      "59-109% of it in the thesis; the range is at the end).** The two programs spend their time differently. Interpreted MATLAB pays a fixed "
      "cost of microseconds per node expansion (function calls, growing arrays, searching the "
      "open list), the same for A* and Theta*, and that fixed cost hides the extra "
      "line-of-sight work, so the thesis's planners run within a factor of 2 of each other. In "
      "C++ an A* expansion costs tens of nanoseconds, while a line-of-sight check walks a "
      "supercover line over tens of cells, so Theta*'s checks dominate and A* is several times "
      "faster. Compare line-of-sight counts and path lengths across the two; compare times only "
      "within one program.\n\n";
  std::vector<JsonObject> rows;
  double astar_ratio_min = 1e300, astar_ratio_max = 0.0;
  const char* planner_names[3] = {"astar", "basic_theta_star", "lazy_theta_star"};
  const auto maps = seed003Maps();
  for (std::size_t k = 0; k < maps.size(); ++k) {
    const Seed003Map& m = maps[k];
    const OccupancyGrid grid = seed003Grid(m);
    GridQuery q;
    q.grid = &grid;
    q.start = grid.cellOf(m.start);
    q.goal = grid.cellOf(m.goal);
    if (m.planar) q.start.z = q.goal.z = 0;
    std::vector<std::unique_ptr<GridPlanner>> planners;
    planners.push_back(std::make_unique<AStar>());
    planners.push_back(std::make_unique<BasicThetaStar>());
    planners.push_back(std::make_unique<LazyThetaStar>());
    Measured ours[3];
    for (int p = 0; p < 3; ++p) {
      for (int r = 0; r < runs; ++r) {
        const GridPlanResult res = planners[p]->solveGrid(q);
        ours[p].success = res.success;
        ours[p].length = res.length;
        ours[p].times_ms.push_back(res.time_ms);
        ours[p].los = res.counters.count("los_checks") ? res.counters.at("los_checks") : -1;
        ours[p].expansions = res.counters.at("expansions");
      }
      // The median: the machine is shared, and a preempted run would skew a mean.
      auto& t = ours[p].times_ms;
      std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
      ours[p].time_ms = t[t.size() / 2];
    }
    const PublishedRow& pub = kPublished[k];
    md += "## " + std::string(kTableNames[k]) + ": " + m.name + "\n\n" + m.description + "\n\n";
    md += "Grid " + std::to_string(grid.nx()) + "x" + std::to_string(grid.ny()) + "x" +
          std::to_string(grid.nz()) + ", " + std::to_string(grid.blockedCount()) +
          " blocked cells; straight line start-goal " + fmt("%.2f", (m.goal - m.start).norm()) +
          " m. Obstacles: " + obstacleList(m.world) + "\n\n";
    md +=
        "| | A* (seed) | A* (ours) | Basic Theta* (seed) | Basic Theta* (ours) | Lazy Theta* "
        "(seed) | Lazy Theta* (ours) |\n|---|---|---|---|---|---|---|\n";
    auto row = [&](const std::string& label, auto seed_value, auto our_value) {
      md += "| " + label;
      for (int p = 0; p < 3; ++p) md += " | " + seed_value(p) + " | " + our_value(p);
      md += " |\n";
    };
    row(
        "path length [m]", [&](int p) { return fmt("%.4f", pub.length[p]); },
        [&](int p) { return ours[p].success ? fmt("%.4f", ours[p].length) : "no path"; });
    row(
        "length vs Basic Theta* (seed: recomputed)",
        [&](int p) { return fmt("%.2f%%", 100 * pub.length[p] / pub.length[1]); },
        [&](int p) { return fmt("%.2f%%", 100 * ours[p].length / ours[1].length); });
    row(
        "time [ms]", [&](int p) { return fmt("%.1f", 1000 * pub.time_s[p]); },
        [&](int p) { return fmt("%.3f", ours[p].time_ms); });
    row(
        "time vs Basic Theta* (seed: recomputed)",
        [&](int p) { return fmt("%.2f%%", 100 * pub.time_s[p] / pub.time_s[1]); },
        [&](int p) { return fmt("%.2f%%", 100 * ours[p].time_ms / ours[1].time_ms); });
    row(
        "line-of-sight checks",
        [&](int p) { return pub.los[p] < 0 ? std::string("-") : fmt("%.0f", pub.los[p]); },
        [&](int p) { return ours[p].los < 0 ? std::string("-") : fmt("%.0f", ours[p].los); });
    row(
        "expansions", [](int) { return std::string("-"); },
        [&](int p) { return fmt("%.0f", ours[p].expansions); });
    astar_ratio_min = std::min(astar_ratio_min, ours[0].time_ms / ours[1].time_ms);
    astar_ratio_max = std::max(astar_ratio_max, ours[0].time_ms / ours[1].time_ms);
    for (int p = 0; p < 3; ++p) {
      JsonObject j;
      j.add("map", m.name)
          .add("planner", planner_names[p])
          .add("success", ours[p].success)
          .add("length_m", ours[p].length)
          .add("length_vs_theta", ours[p].length / ours[1].length)
          .add("time_ms_median", ours[p].time_ms)
          .add("time_vs_theta", ours[p].time_ms / ours[1].time_ms)
          .add("los_checks", ours[p].los < 0 ? NAN : ours[p].los)
          .add("expansions", ours[p].expansions)
          .add("seed_length_m", pub.length[p])
          .add("seed_length_vs_theta_recomputed", pub.length[p] / pub.length[1])
          .add("seed_time_s", pub.time_s[p])
          .add("seed_time_vs_theta_recomputed", pub.time_s[p] / pub.time_s[1])
          .add("seed_los_checks", pub.los[p] < 0 ? NAN : pub.los[p]);
      rows.push_back(j);
    }
    md += "\nBasic/Lazy line-of-sight ratio: seed " + fmt("%.2f", pub.los[1] / pub.los[2]) +
          "x, ours " + fmt("%.2f", ours[1].los / ours[2].los) + "x.\n\n";
  }
  md +=
      "Notes. Our Lazy Theta* re-queues a cell whose line-of-sight check fails and whose cost "
      "rises (see planning/grid/lazy_theta_star.h), so it is never longer than A*; the "
      "thesis's Lazy Theta* was longer than its A* on 3D map 1. Times here are C++ and "
      "milliseconds; the thesis's MATLAB times are seconds. A* / Basic Theta* time over the four "
      "maps: ours " +
      fmt("%.1f", 100 * astar_ratio_min) + "-" + fmt("%.1f", 100 * astar_ratio_max) +
      "%, the thesis 58.7-109.3%.\n";
  return {md, rows};
}

}  // namespace cosim::reproduce
