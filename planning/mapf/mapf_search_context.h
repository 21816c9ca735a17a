#pragma once
// What every multi-agent planner needs during one solve(), as SamplingContext is for the
// sampling planners: the instance, its deadline (the query's time limit inside the caller's
// StopToken), the grid the grid planners search (built on first use), the agents' start and goal
// cells, per-agent goal-distance heuristics, and the early returns they share (time up, an
// unreachable goal) with the time filled in.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/stop_token.h"
#include "planning/mapf/goal_distance.h"
#include "planning/mapf/mapf_grid.h"
#include "planning/mapf/mapf_problem.h"

namespace cosim {

class MapfSearchContext {
 public:
  MapfSearchContext(const MapfQuery& query, const StopToken& stop);

  const MapfInstance& instance() const { return *instance_; }
  int agentCount() const { return instance_->agentCount(); }
  std::uint64_t seed() const { return seed_; }
  const StopToken& deadline() const { return deadline_; }
  // The instance's grid with its connectivity (built on the first call).
  const MapfGrid& grid();
  // Agent a's start and goal as grid cell ids.
  int start(int agent) { return grid().id(instance_->starts[agent]); }
  int goal(int agent) { return grid().id(instance_->goals[agent]); }

  // One heuristic per agent towards its goal: the true distance (Reverse Resumable A* from the
  // goal towards the start, Silver 2005) or the plain grid lower bound. Empty when the deadline
  // ran out before every agent had one.
  enum class Heuristic { kTrueDistance, kGridLowerBound };
  std::vector<std::unique_ptr<GoalDistance>> goalDistances(Heuristic kind);

  // Ends the search: `result` with its time filled in.
  MapfResult finish(MapfResult result) const;
  // The search ran out of time before it began: "time limit reached", Timeout (or Stopped).
  MapfResult timeUp() const;
  // Why agent `agent`'s goal was found unreachable: the deadline, if it cut the search short.
  std::string unreachableMessage(int agent) const;
  // Agent `agent`'s goal is unreachable (or the deadline cut its search short).
  MapfResult unreachable(int agent) const;

 private:
  const MapfInstance* instance_;
  std::uint64_t seed_;
  StopToken deadline_;
  std::optional<MapfGrid> grid_;
};

}  // namespace cosim
