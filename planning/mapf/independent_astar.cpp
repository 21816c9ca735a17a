#include "planning/mapf/independent_astar.h"

#include "planning/mapf/mapf_grid.h"
#include "planning/mapf/solution_validator.h"
#include "planning/mapf/spatial_astar.h"

namespace cosim {

MapfResult IndependentAStar::solve(const MapfQuery& query) {
  const StopToken deadline(query.time_limit_s, query.stop);
  const MapfInstance& inst = *query.instance;
  const MapfGrid grid(inst.grid, inst.connectivity);
  MapfResult result;
  long expansions = 0;
  for (int a = 0; a < inst.agentCount(); ++a) {
    SpatialAStarRequest request;
    request.start = grid.id(inst.starts[a]);
    request.goal = grid.id(inst.goals[a]);
    request.deadline = &deadline;
    const SpatialAStarResult path = spatialAStar(grid, request);
    expansions += path.expansions;
    if (path.cells.empty()) {
      result.message = deadline.expired()
                           ? "time limit reached"
                           : "goal of agent " + std::to_string(a) + " is unreachable";
      result.status = deadline.expired() ? expiredStatus(deadline) : PlannerStatus::NoSolution;
      result.paths.clear();
      break;
    }
    result.paths.push_back(grid.toCells(path.cells));
  }
  if (result.message.empty()) {
    const MapfValidation check = validateMapfSolution(inst, result.paths);
    result.success = check.valid();
    result.status = searchStatus(result.success, deadline, PlannerStatus::ApproximateSolution);
    if (!result.success)
      result.message = std::to_string(check.conflicts.size()) + " conflicts between the paths";
  }
  result.counters["expansions"] = static_cast<double>(expansions);
  result.time_ms = deadline.elapsedMs();
  return result;
}

}  // namespace cosim
