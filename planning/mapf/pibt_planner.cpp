#include "planning/mapf/pibt_planner.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "planning/mapf/goal_distance_table.h"
#include "planning/mapf/graph_instance.h"
#include "planning/mapf/mapf_search_context.h"
#include "planning/mapf/pibt_step.h"

namespace cosim {

MapfResult PibtPlanner::solve(const MapfQuery& query, const StopToken& stop) {
  const MapfSearchContext context(query, stop);
  const StopToken& deadline = context.deadline();
  const GraphInstance g = graphInstance(context.instance());
  const int n = context.agentCount();
  const int max_steps =
      options_.max_steps > 0 ? options_.max_steps : std::max(1000, g.graph.vertexCount());
  MapfResult result;
  const auto finish = [&](std::string message) {
    result.message = std::move(message);
    return context.finish(std::move(result));
  };
  const GoalDistanceTable distance(g.graph, g.goals);
  const std::string unreachable = checkGoalsReachable(distance, g.starts, deadline);
  if (!unreachable.empty()) {
    result.status = searchStatus(false, deadline, PlannerStatus::NoSolution);
    return finish(unreachable);
  }

  // Priorities as LaCAM's reference code starts them (d_i(start) / N), then PIBT's: +1 per step
  // off the goal, back to the fractional part (a fixed tie-breaker) on it.
  std::vector<float> priority(n);
  for (int i = 0; i < n; ++i)
    priority[i] = static_cast<float>(distance(i, g.starts[i])) / static_cast<float>(n);
  std::vector<int> order(n);
  std::vector<std::vector<int>> configurations = {g.starts};
  PibtStep step(g.graph, distance, g.goals, options_.swap);
  SplitMix64 rng(context.seed());
  std::vector<int> next(n);
  PlannerStatus gave_up = PlannerStatus::ApproximateSolution;  // the paths so far, off the goals
  while (configurations.back() != g.goals) {
    const int t = static_cast<int>(configurations.size()) - 1;
    if (t >= max_steps) {
      result.message = "not all agents arrived within " + std::to_string(max_steps) + " steps";
      break;
    }
    if (deadline.expired()) {
      result.message = deadline.stopRequested() ? "stopped" : "time limit reached";
      break;
    }
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      return priority[a] > priority[b] || (priority[a] == priority[b] && a < b);
    });
    // Without fixed moves every agent can at least stay, so a step does not fail.
    if (!step.next(configurations.back(), order, {}, rng, next)) {
      result.message = "PIBT found no move at t=" + std::to_string(t);
      gave_up = PlannerStatus::NoSolution;
      break;
    }
    configurations.push_back(next);
    for (int i = 0; i < n; ++i)
      priority[i] =
          next[i] != g.goals[i] ? priority[i] + 1.0f : priority[i] - std::floor(priority[i]);
  }
  result.success = result.message.empty();
  result.status = searchStatus(result.success, deadline, gave_up);
  // On failure the paths so far (not a solution: they end off the goals).
  result.paths = pathsOfConfigurations(g.graph, configurations, n);
  result.counters["steps"] = static_cast<double>(configurations.size() - 1);
  result.counters["distance_table_mb"] = static_cast<double>(distance.bytesReached()) / (1 << 20);
  return context.finish(std::move(result));
}

}  // namespace cosim
