#include "planning/swarm/layer_walk_search.h"

namespace cosim {

LayerWalkSearch::LayerWalkSearch(const GridQuery& query, const StopToken& stop, int directions)
    : deadline_(query.time_limit_s, stop),
      layer_(planarLayerFor(query)),
      moves_(directions),
      walker_(layer_.grid, moves_) {}

bool LayerWalkSearch::offer(const std::vector<Cell>& path, double length, int iteration) {
  if (!(length < best_length_ - 1e-12)) return false;
  best_length_ = length;
  best_ = path;
  best_iteration_ = iteration;
  return true;
}

GridPlanResult LayerWalkSearch::failure(const std::string& message, PlannerStatus status) const {
  GridPlanResult result;
  result.message = message;
  result.status = status;
  result.counters["expansions"] = static_cast<double>(walker_.steps());
  result.time_ms = deadline_.elapsedMs();
  return result;
}

GridPlanResult LayerWalkSearch::result(const std::string& no_path, int iterations) const {
  if (unreachable()) return failure("goal unreachable from start", PlannerStatus::NoSolution);
  GridPlanResult result = failure(best_.empty() ? no_path : "",
                                  searchStatus(!best_.empty(), deadline_, PlannerStatus::LimitReached));
  result.counters["iterations"] = iterations;
  result.counters["best_iteration"] = best_iteration_;
  if (!best_.empty()) {
    result.success = true;
    result.cells = liftFromLayer(best_, layer_);
    result.length = gridPathLength(result.cells);
  }
  return result;
}

}  // namespace cosim
