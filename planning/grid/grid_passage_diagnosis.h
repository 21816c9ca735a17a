#pragma once
// Why a grid planner found no path through a world: the vehicle's inflation, the resolution, a
// blocked start or goal cell, and the widest passage between start and goal (the largest
// clearance a chain of neighbouring cells from start to goal keeps from every obstacle). The
// widest passage is a bottleneck (maximin) search over cell centres, run only after a failure.
#include <string>

#include "planning/grid/occupancy_grid.h"

namespace cosim {

struct WidestPassage {
  bool joined = false;     // some chain of cells outside the obstacles joins start and goal
  double clearance = 0.0;  // the chain's least centre clearance, metres (uninflated obstacles)
  bool capped = false;     // clearance reached the search's cap: it is at least that much
};

// The widest passage between the cells start and goal of `layout` (a grid of `world`: its
// cells' centres are measured), over 8 (2D) or 26 (3D) neighbours. Clearances are capped at
// `cap` metres, which bounds the work to the cells near obstacles. 3D: the floor counts as an
// obstacle.
WidestPassage widestPassage(const World& world, const OccupancyGrid& layout, const Cell& start,
                            const Cell& goal, bool planar, double cap);

// What a grid planner on `grid` reports when it found no path. `search_message` is the search's
// own ("no path", "time limit"); when the search was exhausted (GridPlanResult::exhausted) the
// message says why no path exists; `blocking` is the cell_blocking mode in force.
std::string explainNoGridPath(const World& world, const OccupancyGrid& grid, const Cell& start,
                              const Cell& goal, double inflation, bool planar,
                              bool search_exhausted, const std::string& search_message,
                              OccupancyGrid::Blocking blocking);

// The cell_blocking name of a blocking mode: "exact", "cell" (AnyPoint) or "centre".
const char* blockingName(OccupancyGrid::Blocking blocking);

// Which end of a path a point is.
enum class PathEnd { Start, Goal };
const char* pathEndName(PathEnd end);  // "start", "goal"

// Why the start or goal cell is blocked: its centre's distance to the nearest obstacle against
// the inflation. p is the exact point.
std::string explainBlockedEnd(const World& world, const OccupancyGrid& grid, PathEnd which,
                              const Eigen::Vector3d& p, double inflation, bool planar);

}  // namespace cosim
