#include "planning/mapf/windowed_hca_star.h"

#include <algorithm>
#include <memory>

#include "planning/mapf/mapf_grid.h"
#include "planning/mapf/reservation_table.h"
#include "planning/mapf/reverse_resumable_astar.h"
#include "planning/mapf/space_time_astar.h"

namespace cosim {

MapfResult WindowedHcaStar::solve(const MapfQuery& query) {
  const StopToken deadline(query.time_limit_s, query.stop);
  const MapfInstance& inst = *query.instance;
  const MapfGrid grid(inst.grid, inst.connectivity);
  const int n = inst.agentCount();
  const bool dynamic = options_.priorities == PriorityPolicy::kDynamic;
  const int max_steps = options_.max_steps > 0 ? options_.max_steps : grid.cellCount();
  MapfResult result;

  std::vector<int> position(n), goal(n);
  std::vector<std::unique_ptr<ReverseResumableAStar>> distance;
  std::vector<std::vector<int>> executed(n);
  for (int a = 0; a < n; ++a) {
    if (deadline.expired()) {
      result.message = "time limit reached";
      result.status = expiredStatus(deadline);
      result.time_ms = deadline.elapsedMs();
      return result;
    }
    position[a] = grid.id(inst.starts[a]);
    goal[a] = grid.id(inst.goals[a]);
    distance.push_back(
        std::make_unique<ReverseResumableAStar>(grid, goal[a], position[a], &deadline));
    executed[a].push_back(position[a]);
    if (distance[a]->distance(position[a]) >= GoalDistance::kUnreachable) {
      // (a distance search cut short by the deadline finds nothing either)
      result.status = searchStatus(false, deadline, PlannerStatus::NoSolution);
      result.message = deadline.expired() ? "time limit reached"
                                          : "goal of agent " + std::to_string(a) + " is unreachable";
      result.time_ms = deadline.elapsedMs();
      return result;
    }
  }

  SpaceTimeAStar search(grid);
  ReservationTable table(grid);
  std::vector<int> priority(n, 0);
  long expansions = 0, rounds = 0, retries = 0;
  int t0 = 0;
  PlannerStatus gave_up = PlannerStatus::NoSolution;  // why the loop ended without a solution
  while (result.message.empty()) {
    if (position == goal) {
      result.success = true;
      break;
    }
    if (t0 >= max_steps) {
      result.message = "not all agents arrived within " + std::to_string(max_steps) + " steps";
      gave_up = PlannerStatus::ApproximateSolution;
      break;
    }
    if (deadline.expired()) {
      result.message = "time limit reached";
      break;
    }
    ++rounds;
    // Seed 004 §4.5: "extend the time window to the max of the priorities", bounded here by the
    // thesis's rule of thumb w = number of agents (§3.5) so that it cannot grow without end.
    const int max_priority = *std::max_element(priority.begin(), priority.end());
    const int window =
        dynamic ? std::min(std::max(options_.window, max_priority), std::max(options_.window, n))
                : options_.window;
    std::vector<std::vector<int>> plans(n);
    for (int attempt = 0;; ++attempt) {
      table.clear();
      int failed = -1;
      for (const int a : planningOrder(priority)) {
        SpaceTimeRequest request;
        request.start = position[a];
        request.goal = goal[a];
        request.start_time = t0;
        request.window = window;
        request.constraints = &table;
        request.heuristic = distance[a].get();
        request.max_expansions = options_.max_expansions;
        request.deadline = &deadline;
        const SpaceTimePlan plan = search.plan(request);
        expansions += plan.expansions;
        if (!plan.found) {
          failed = a;
          break;
        }
        table.reservePath(plan.cells, t0, /*park=*/false);
        plans[a] = plan.cells;
      }
      if (failed < 0) break;
      if (deadline.expired()) {
        result.message = "time limit reached";
        break;
      }
      if (!dynamic || attempt >= n) {
        result.message = "agent " + std::to_string(failed) +
                         " found no route in the window at t=" + std::to_string(t0);
        break;
      }
      // Seed 004 §4.5: the agent without a route gets the highest priority; plan again.
      ++retries;
      priority[failed] = *std::max_element(priority.begin(), priority.end()) + 1;
    }
    if (!result.message.empty()) break;

    const int steps = options_.replan_every > 0 ? std::min(options_.replan_every, window)
                                                : std::max(1, window / 2);
    for (int a = 0; a < n; ++a) {
      const int before = distance[a]->distance(position[a]);
      for (int i = 1; i <= steps; ++i) executed[a].push_back(plans[a][i]);
      position[a] = plans[a][steps];
      // Seed 004 §4.5: "raise the priority in each step if no route was found, and retry in the
      // next step": an agent that got no closer to its goal is planned earlier next time.
      if (dynamic && position[a] != goal[a] && distance[a]->distance(position[a]) >= before)
        ++priority[a];
    }
    t0 += steps;
  }
  result.status = searchStatus(result.success, deadline, gave_up);
  for (int a = 0; a < n; ++a) {
    MapfPath path = grid.toCells(executed[a]);
    if (result.success) trimWaitsAtEnd(path);
    result.paths.push_back(std::move(path));
  }
  result.counters["expansions"] = static_cast<double>(expansions);
  result.counters["rounds"] = static_cast<double>(rounds);
  result.counters["priority_retries"] = static_cast<double>(retries);
  result.time_ms = deadline.elapsedMs();
  return result;
}

}  // namespace cosim
