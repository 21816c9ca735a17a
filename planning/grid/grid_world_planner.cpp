#include "planning/grid/grid_world_planner.h"

#include <memory>
#include <tuple>

#include "core/input_error.h"
#include "core/stop_token.h"
#include "planning/grid/grid_passage_diagnosis.h"
#include "planning/grid/grid_segment_checker.h"
#include "planning/sampling/collision_world.h"

namespace cosim {

namespace {

// The search runs between cell centres, so the path used to go from the exact start to its
// cell's centre and on, and from the goal cell's centre to the exact goal: a hook of up to half
// a cell at each end, turning back on itself where the path leaves the cell the other way. The
// start's cell centre is dropped where the straight segment from the start to the next point
// keeps the inflation clear of every obstacle (checked exactly, as any edge); the goal's alike.
// Not for Blocking::Centre, a thesis's own grid rule whose plans are reproduced as they were.
void dropEndCellCentres(const World& world, double inflation, bool planar, Path& path) {
  std::vector<Eigen::Vector3d>& w = path.waypoints;
  if (w.size() < 3) return;
  const CollisionWorld clear(world, inflation, 0.0, planar);
  if (clear.segmentFree(w[0], w[2])) w.erase(w.begin() + 1);
  const std::size_t n = w.size();
  if (n >= 3 && clear.segmentFree(w[n - 3], w[n - 1]))
    w.erase(w.begin() + static_cast<long>(n) - 2);
}

}  // namespace

PlanResult GridWorldPlanner::solve(const PlanningProblem& problem, const StopToken& stop) {
  const StopToken clock(problem.time_limit_s, stop);
  const double plane_z = problem.start.z();
  const OccupancyGrid grid = OccupancyGrid::fromWorld(
      *problem.world, resolution_, problem.inflation, problem.planar, plane_z, blocking_);
  std::unique_ptr<GridSegmentChecker> segments;
  if (blocking_ == OccupancyGrid::Blocking::Exact)
    segments = std::make_unique<GridSegmentChecker>(*problem.world, grid, problem.inflation,
                                                    problem.planar, plane_z);
  GridQuery query;
  query.grid = &grid;
  query.segments = segments.get();
  query.start = grid.cellOf(problem.start);
  query.goal = grid.cellOf(problem.goal);
  query.time_limit_s = problem.time_limit_s;
  query.seed = problem.seed;

  PlanResult result;
  result.counters["grid_cells"] = static_cast<double>(grid.cellCount());
  auto finish = [&] {
    if (segments) result.counters["segment_checks"] = segments->exactChecks();
    result.time_ms = clock.elapsedMs();
    return result;
  };
  for (const auto& [which, p, c] : {std::tuple(PathEnd::Start, problem.start, query.start),
                                    std::tuple(PathEnd::Goal, problem.goal, query.goal)})
    if (grid.blocked(c)) {
      result.status =
          which == PathEnd::Start ? PlannerStatus::InvalidStart : PlannerStatus::InvalidGoal;
      result.message =
          explainBlockedEnd(*problem.world, grid, which, p, problem.inflation, problem.planar);
      return finish();
    }
  // The exact endpoints are joined to the centres of their own cells; with exact occupancy the
  // joining segment is checked like every other edge (the point and the centre are both free,
  // the segment between them need not be).
  const Eigen::Vector3d start_centre = grid.cellCenter(query.start),
                        goal_centre = grid.cellCenter(query.goal);
  auto joined = [&](const Eigen::Vector3d& p, Eigen::Vector3d centre) {
    if (problem.planar) centre.z() = p.z();
    return !segments || segments->pointsClear(p, centre);
  };
  for (const auto& [which, p, centre] : {std::tuple(PathEnd::Start, problem.start, start_centre),
                                         std::tuple(PathEnd::Goal, problem.goal, goal_centre)})
    if (!joined(p, centre)) {
      result.status =
          which == PathEnd::Start ? PlannerStatus::InvalidStart : PlannerStatus::InvalidGoal;
      result.message = std::string(pathEndName(which)) +
                       " cannot reach the centre of its cell in a straight "
                       "line at resolution " +
                       std::to_string(resolution_) +
                       " m (an inflated obstacle is in between); try a finer resolution";
      return finish();
    }

  GridPlanResult g = planner_->solveGrid(query, stop);
  for (const auto& [k, v] : g.counters) result.counters[k] = v;
  result.success = g.success;
  result.status = g.status;
  if (!g.success)
    result.message =
        explainNoGridPath(*problem.world, grid, query.start, query.goal, problem.inflation,
                          problem.planar, g.exhausted, g.message, blocking_);
  if (g.success) {
    // Every segment between centres was checked by the planner (an any-angle segment from the
    // exact point itself could clip a blocked cell).
    result.path.waypoints.push_back(problem.start);
    for (const Cell& c : g.cells) {
      const Eigen::Vector3d p = grid.cellCenter(c);
      if ((p - result.path.waypoints.back()).norm() > 1e-9) result.path.waypoints.push_back(p);
    }
    if ((problem.goal - result.path.waypoints.back()).norm() > 1e-9)
      result.path.waypoints.push_back(problem.goal);
    if (problem.planar)
      for (auto& p : result.path.waypoints) p.z() = problem.start.z();
    if (blocking_ != OccupancyGrid::Blocking::Centre)
      dropEndCellCentres(*problem.world, problem.inflation, problem.planar, result.path);
  }
  return finish();
}

}  // namespace cosim
