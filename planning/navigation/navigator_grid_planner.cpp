#include "planning/navigation/navigator_grid_planner.h"

#include "core/stop_token.h"

namespace cosim {

GridPlanResult NavigatorGridPlanner::solveGrid(const GridQuery& query, const StopToken& stop) {
  const StopToken clock(query.time_limit_s, stop);
  GridPlanResult result;
  const OccupancyGrid& g = *query.grid;
  if (query.start.z != query.goal.z) {
    result.status = PlannerStatus::InvalidProblem;
    result.message = "2D navigator: start and goal must lie on the same grid layer";
    return result;
  }
  OccupancyGrid layer(g.nx(), g.ny(), 1, g.cellSize(), g.origin());
  for (int y = 0; y < g.ny(); ++y)
    for (int x = 0; x < g.nx(); ++x) layer.setBlocked(x, y, 0, g.blocked(x, y, query.start.z));
  const NavigationWorld world(std::move(layer));
  NavigationLimits limits;
  limits.time_limit_s = query.time_limit_s;
  limits.stop = &stop;
  std::unique_ptr<Navigator> navigator = make_();
  const NavigationRun run = runNavigation(*navigator, world, {query.start.x, query.start.y, 0},
                                          {query.goal.x, query.goal.y, 0}, limits, query.seed);
  result.success = run.reached;
  result.message = run.message;
  result.status = run.status;
  for (const Cell& c : run.cells) result.cells.push_back({c.x, c.y, query.start.z});
  result.length = run.reached ? run.length : 0.0;
  result.counters["steps"] = run.steps;
  result.counters["waits"] = run.waits;
  result.counters["replans"] = run.replans;
  result.counters["mean_plan_ms"] = run.mean_plan_ms;
  result.counters["max_plan_ms"] = run.max_plan_ms;
  result.time_ms = clock.elapsedMs();
  return result;
}

}  // namespace cosim
