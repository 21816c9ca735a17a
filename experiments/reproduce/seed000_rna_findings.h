#pragma once
// seed000-rna's closing section and maps: the runs of each navigator summed up per table, the
// thesis's RNA findings (Pěňčík 2014, §6.3, claim 14 of its summary) checked against them, and
// the map figures of the dead end, scene 2, a random map and the moving obstacles.
#include <map>
#include <string>
#include <vector>

#include "experiments/reproduce/agreement_section.h"
#include "experiments/reproduce/reproduction.h"
#include "experiments/reproduce/seed000_runs.h"
#include "planning/navigation/navigation_world.h"
#include "planning/navigation/navigator.h"

namespace cosim::reproduce {

// The runs of one navigator in one setting.
struct NavigationStats {
  int runs = 0, reached = 0, collisions = 0, waits = 0;
  double length = 0, length_sq = 0, plan_ms = 0, max_plan_ms = 0, replans = 0;
  std::vector<Cell> shortest;  // the shortest executed path (for the map figures)
  double shortest_length = 0;
  std::map<std::string, int> endings;  // why the runs that did not arrive ended, with counts
  double mean() const { return reached ? length / reached : std::nan(""); }
  // Two standard errors of the mean length (0 with fewer than two arrivals).
  double twoSe() const {
    if (reached < 2) return 0.0;
    const double var = (length_sq - length * length / reached) / (reached - 1);
    return 2.0 * std::sqrt(std::max(0.0, var) / reached);
  }
  // Counts one run; its path becomes `shortest` if it arrived by the shortest path so far.
  void add(const NavigationRun& run);
};

// Every table of the report, per navigator ("rna", "wf_rna", "d_star_lite").
struct RnaTables {
  std::vector<int> dead_end_sights, scene2_sights;
  std::map<std::string, std::vector<NavigationStats>> dead_end, scene2;  // per navigator, per sight
  std::map<std::string, NavigationStats> random_maps;
  NavigationStats scene2_many_waits;  // RNA at scene 2's smallest sight, max_waits 200
  NavigationStats moving[2][3];       // [prediction][navigator]
  int maps = 0;
  double opt_dead_end = 0, opt2 = 0;
};

// Mean lengths per sight of one navigator, "a / b / c".
std::string lengths(const std::vector<NavigationStats>& by_sight);

// The thesis's findings against the tables.
std::vector<Finding> rnaFindings(const RnaTables& t);

// Writes seed000-rna_map1..4 (the dead end, scene 2, the first random map, scene 1 with moving
// obstacles, each with the navigators' shortest paths) and returns the report's section.
std::string rnaMaps(const Options& options, const RnaTables& t, const Seed000Scene& dead_end,
                    const Seed000Scene& scene2, const Seed000Scene& scene1,
                    const OccupancyGrid& random_map, const NavigationWorld& moving);

}  // namespace cosim::reproduce
