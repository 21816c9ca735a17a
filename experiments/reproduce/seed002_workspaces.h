#pragma once
// The three workspaces of seed 002, part A (its Figure 3-2, missing from the text), rebuilt to
// the structure its numbers state, with its start and target points and its published lengths.
// 500 cm x 500 cm at 5 cm per cell (100 x 100 cells; the seed's coordinates run to 465); start
// points (5,50) .. (30,65) near one corner, targets (400,450) .. (465,460) near the opposite one.
// The seed's ant and GA lengths agree within 0.4-1.3 %, so both are read as near-optimal and the
// rectangular obstacles are placed so that each query's optimum (A*, 8 directions, no corner
// cutting) is about 98 % of the seed's ant length:
//  - workspace 1 (4 obstacles): small detours;
//  - workspace 2 (+4): a walled pocket around the target (400,450) whose only entrance is a
//    channel under it, reached from the far side, so only that query's path jumps (as the seed's
//    610 -> 919 cm) while the targets (460,455) and (465,460) beside it stay outside;
//  - workspace 3 (+6): clutter off the optimal routes (the seed's workspace-3 lengths are within
//    1 % of its workspace-2 lengths).
#include <string>
#include <vector>

#include "planning/grid/occupancy_grid.h"

namespace cosim::reproduce {

constexpr double kSeed002CellCm = 5.0;

struct Seed002Rect {
  int x0, y0, x1, y1;  // inclusive cell ranges
};

struct Seed002Workspace {
  const char* name;
  std::vector<Seed002Rect> obstacles;
  int ants, ant_iterations;                // the seed's convergence table (ACO columns)
  int population, generations;             // (GA columns)
  double seed_time_ant_s, seed_time_ga_s;  // the seed's time table
};

struct Seed002Query {
  int sx, sy, tx, ty;  // cm
  Cell start() const;  // the cell of (sx, sy): coordinate / 5 cm
  Cell target() const;
};

// The seed's three start-target pairs, in its order.
const std::vector<Seed002Query>& seed002Queries();

// The seed's path lengths (cm): [workspace][query] = {ant, genetic}.
extern const double kSeed002Length[3][3][2];

// Relatively simple, relatively complex, complex.
std::vector<Seed002Workspace> seed002Workspaces();

OccupancyGrid seed002Grid(const Seed002Workspace& w);

}  // namespace cosim::reproduce
