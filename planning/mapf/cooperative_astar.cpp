#include "planning/mapf/cooperative_astar.h"

#include <algorithm>
#include <memory>

#include "planning/mapf/mapf_search_context.h"
#include "planning/mapf/reservation_table.h"
#include "planning/mapf/space_time_astar.h"

namespace cosim {

MapfResult CooperativeAStar::solve(const MapfQuery& query, const StopToken& stop) {
  MapfSearchContext context(query, stop);
  const StopToken& deadline = context.deadline();
  const MapfGrid& grid = context.grid();
  const int n = context.agentCount();
  MapfResult result;
  const std::vector<std::unique_ptr<GoalDistance>> heuristic = context.goalDistances(
      options_.abstract_heuristic ? MapfSearchContext::Heuristic::kTrueDistance
                                  : MapfSearchContext::Heuristic::kGridLowerBound);
  if (static_cast<int>(heuristic.size()) < n) return context.timeUp();
  SpaceTimeAStar search(grid);
  ReservationTable table(grid);
  std::vector<int> priority(n, 0);
  long expansions = 0;
  int restarts = 0;
  // Dynamic priorities (seed 004 §4.5): the agent that found no route is raised above all
  // others and everyone is planned again; at most n times, so the loop ends.
  for (;; ++restarts) {
    table.clear();
    std::vector<std::vector<int>> plans(n);
    int failed = -1;
    bool out_of_budget = false;
    for (const int a : planningOrder(priority)) {
      SpaceTimeRequest request;
      request.start = context.start(a);
      request.goal = context.goal(a);
      request.constraints = &table;
      request.heuristic = heuristic[a].get();
      request.max_expansions = options_.max_expansions;
      request.deadline = &deadline;
      const SpaceTimePlan plan = search.plan(request);
      expansions += plan.expansions;
      if (!plan.found) {
        failed = a;
        out_of_budget = plan.out_of_budget || deadline.expired();
        break;
      }
      table.reservePath(plan.cells, 0, /*park=*/true);
      plans[a] = plan.cells;
    }
    if (failed < 0) {
      result.success = true;
      result.status = searchStatus(true, deadline, PlannerStatus::NoSolution);
      for (const auto& p : plans) result.paths.push_back(grid.toCells(p));
      break;
    }
    const bool may_retry =
        options_.priorities == PriorityPolicy::kDynamic && restarts < n && !out_of_budget;
    if (!may_retry) {
      result.message = out_of_budget ? "time or expansion limit reached while planning agent " +
                                           std::to_string(failed)
                                     : "no route for agent " + std::to_string(failed) +
                                           " around the higher-priority agents";
      result.status = searchStatus(
          false, deadline, out_of_budget ? PlannerStatus::LimitReached : PlannerStatus::NoSolution);
      break;
    }
    priority[failed] = *std::max_element(priority.begin(), priority.end()) + 1;
  }
  result.counters["expansions"] = static_cast<double>(expansions);
  result.counters["restarts"] = restarts;
  return context.finish(std::move(result));
}

}  // namespace cosim
