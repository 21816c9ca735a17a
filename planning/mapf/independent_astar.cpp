#include "planning/mapf/independent_astar.h"

#include "planning/mapf/mapf_search_context.h"
#include "planning/mapf/solution_validator.h"
#include "planning/mapf/spatial_astar.h"

namespace cosim {

MapfResult IndependentAStar::solve(const MapfQuery& query, const StopToken& stop) {
  MapfSearchContext context(query, stop);
  const StopToken& deadline = context.deadline();
  const MapfGrid& grid = context.grid();
  MapfResult result;
  long expansions = 0;
  for (int a = 0; a < context.agentCount(); ++a) {
    SpatialAStarRequest request;
    request.start = context.start(a);
    request.goal = context.goal(a);
    request.deadline = &deadline;
    const SpatialAStarResult path = spatialAStar(grid, request);
    expansions += path.expansions;
    if (path.cells.empty()) {
      result.message = context.unreachableMessage(a);
      result.status = deadline.expired() ? expiredStatus(deadline) : PlannerStatus::NoSolution;
      result.paths.clear();
      break;
    }
    result.paths.push_back(grid.toCells(path.cells));
  }
  if (result.message.empty()) {
    const MapfValidation check = validateMapfSolution(context.instance(), result.paths);
    result.success = check.valid();
    result.status = searchStatus(result.success, deadline, PlannerStatus::ApproximateSolution);
    if (!result.success)
      result.message = std::to_string(check.conflicts.size()) + " conflicts between the paths";
  }
  result.counters["expansions"] = static_cast<double>(expansions);
  return context.finish(std::move(result));
}

}  // namespace cosim
