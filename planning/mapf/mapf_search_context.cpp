#include "planning/mapf/mapf_search_context.h"

#include "planning/mapf/reverse_resumable_astar.h"

namespace cosim {

MapfSearchContext::MapfSearchContext(const MapfQuery& query, const StopToken& stop)
    : instance_(query.instance), seed_(query.seed), deadline_(query.time_limit_s, stop) {}

const MapfGrid& MapfSearchContext::grid() {
  if (!grid_) grid_.emplace(instance_->grid, instance_->connectivity);
  return *grid_;
}

std::vector<std::unique_ptr<GoalDistance>> MapfSearchContext::goalDistances(Heuristic kind) {
  std::vector<std::unique_ptr<GoalDistance>> distance;
  for (int a = 0; a < agentCount(); ++a) {
    if (deadline_.expired()) return {};
    if (kind == Heuristic::kTrueDistance)
      distance.push_back(
          std::make_unique<ReverseResumableAStar>(grid(), goal(a), start(a), &deadline_));
    else
      distance.push_back(std::make_unique<GridLowerBoundDistance>(grid(), goal(a)));
  }
  return distance;
}

MapfResult MapfSearchContext::finish(MapfResult result) const {
  result.time_ms = deadline_.elapsedMs();
  return result;
}

MapfResult MapfSearchContext::timeUp() const {
  MapfResult result;
  result.message = "time limit reached";
  result.status = expiredStatus(deadline_);
  return finish(std::move(result));
}

std::string MapfSearchContext::unreachableMessage(int agent) const {
  return deadline_.expired() ? "time limit reached"
                             : "goal of agent " + std::to_string(agent) + " is unreachable";
}

MapfResult MapfSearchContext::unreachable(int agent) const {
  MapfResult result;
  result.status = searchStatus(false, deadline_, PlannerStatus::NoSolution);
  result.message = unreachableMessage(agent);
  return finish(std::move(result));
}

}  // namespace cosim
