#pragma once
// The interface of planners that search an occupancy grid (A*, Theta*, ant colonies, ...).
// `cosim grid-bench` calls them on MovingAI maps directly; `cosim plan/run` call them through
// GridWorldPlanner, which voxelises the scenario's world first.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "planning/grid/occupancy_grid.h"
#include "planning/planner_status.h"

namespace cosim {

// Which moves a grid search may make.
struct GridMoves {
  // 2D: 4 or 8; 3D: 6 or 26 (18 is also accepted: faces + edges).
  int connectivity = 8;
  // false: a diagonal move needs every orthogonal side cell it passes free (seed 004 and the
  // MovingAI benchmarks); true: only the target cell must be free (most of seed 000).
  bool corner_cutting = false;
};

// A move (dx, dy, dz) allowed by `moves` on a grid of the given dimensionality, with its length
// in cells (1, sqrt 2, sqrt 3).
struct GridStep {
  int dx, dy, dz;
  double cost;
};
std::vector<GridStep> gridSteps(const GridMoves& moves, bool three_d);

// True if the step from c is legal: target free and, without corner cutting, every cell that
// the diagonal move sweeps past free as well.
bool gridStepAllowed(const OccupancyGrid& grid, const Cell& c, const GridStep& step,
                     bool corner_cutting);

class GridSegmentChecker;

struct GridQuery {
  const OccupancyGrid* grid = nullptr;
  // When set (grids judged at cell centres), moves and lines of sight must also clear the
  // inflated obstacles; only planners whose checksSegments() is true honour it.
  const GridSegmentChecker* segments = nullptr;
  Cell start, goal;
  double time_limit_s = 10.0;
  std::uint64_t seed = 1;
};

struct GridPlanResult {
  bool success = false;  // status == ExactSolution
  PlannerStatus status = PlannerStatus::Unknown;
  std::vector<Cell> cells;  // start ... goal; any-angle planners return only the turning cells
  double length = 0.0;      // in cell units (Euclidean between consecutive cells)
  double time_ms = 0.0;
  std::map<std::string, double> counters;  // expansions, los_checks, iterations, ...
  std::string message;                     // why it failed, empty on success
  // The search covered every cell it could reach without finding the goal: a complete "no path"
  // (not a time limit, and not a navigator that gave up), which GridWorldPlanner explains.
  bool exhausted = false;
};

class GridPlanner {
 public:
  virtual ~GridPlanner() = default;
  virtual std::string name() const = 0;
  // `stop`: the caller's StopToken, as for Planner::solve (the search also ends at
  // query.time_limit_s).
  virtual GridPlanResult solveGrid(const GridQuery& query, const StopToken& stop) = 0;
  // True if solveGrid honours GridQuery::segments (then worlds may be voxelised with
  // OccupancyGrid::Blocking::Exact); the others get the conservative AnyPoint grid.
  virtual bool checksSegments() const { return false; }
};

// Euclidean length of a cell sequence, in cells.
double gridPathLength(const std::vector<Cell>& cells);

}  // namespace cosim
