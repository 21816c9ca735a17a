#include "planning/grid/grid_world_planner.h"

#include "planning/deadline.h"
#include "planning/input_error.h"

namespace cosim {

PlanResult GridWorldPlanner::solve(const PlanningProblem& problem) {
  const Deadline clock(problem.time_limit_s);
  const OccupancyGrid grid = OccupancyGrid::fromWorld(
      *problem.world, resolution_, problem.inflation, problem.planar, problem.start.z(), blocking_);
  GridQuery query;
  query.grid = &grid;
  query.start = grid.cellOf(problem.start);
  query.goal = grid.cellOf(problem.goal);
  query.time_limit_s = problem.time_limit_s;
  query.seed = problem.seed;

  PlanResult result;
  result.counters["grid_cells"] = static_cast<double>(grid.cellCount());
  if (grid.blocked(query.start) || grid.blocked(query.goal)) {
    result.message = std::string(grid.blocked(query.start) ? "start" : "goal") +
                     " cell is blocked at resolution " + std::to_string(resolution_) +
                     " m with the vehicle's inflation";
    result.time_ms = clock.elapsedMs();
    return result;
  }
  GridPlanResult g = planner_->solveGrid(query);
  for (const auto& [k, v] : g.counters) result.counters[k] = v;
  result.success = g.success;
  result.message = g.message;
  if (g.success) {
    // The exact endpoints are joined to the centres of their own cells: that short segment stays
    // inside a free cell, while every segment between centres was checked by the planner (an
    // any-angle segment from the exact point itself could clip a blocked cell).
    result.path.waypoints.push_back(problem.start);
    for (const Cell& c : g.cells) {
      const Eigen::Vector3d p = grid.cellCenter(c);
      if ((p - result.path.waypoints.back()).norm() > 1e-9) result.path.waypoints.push_back(p);
    }
    if ((problem.goal - result.path.waypoints.back()).norm() > 1e-9)
      result.path.waypoints.push_back(problem.goal);
    if (problem.planar)
      for (auto& p : result.path.waypoints) p.z() = problem.start.z();
  }
  result.time_ms = clock.elapsedMs();
  return result;
}

}  // namespace cosim
