#include "planning/mapf/conflict_based_search.h"

#include "planning/mapf/mapf_search_context.h"

namespace cosim {

namespace {

// The message and, when neither the deadline nor a stop ended the search, the status of a
// search that ended without a solution.
std::pair<std::string, PlannerStatus> failure(const CbsOutcome& outcome) {
  using Status = CbsOutcome::Status;
  switch (outcome.status) {
    case Status::kSolved:
      return {"", PlannerStatus::NoSolution};
    case Status::kTimeLimit:
      return {"time limit reached", PlannerStatus::Timeout};
    case Status::kUnreachable:
      return {"goal of agent " + std::to_string(outcome.agent) + " is unreachable",
              PlannerStatus::NoSolution};
    case Status::kRootSearchLimit:  // the deadline or the low level's max_expansions
      return {"time limit reached", PlannerStatus::LimitReached};
    case Status::kNodeLimit:
      return {"constraint-tree node limit (max_nodes) reached", PlannerStatus::LimitReached};
    case Status::kTreeExhausted:
      return {"no solution (constraint tree exhausted)", PlannerStatus::NoSolution};
    case Status::kLowLevelLimit:
      return {"low-level search limit reached", PlannerStatus::LimitReached};
  }
  return {"", PlannerStatus::Unknown};
}

}  // namespace

MapfResult ConflictBasedSearch::solve(const MapfQuery& query, const StopToken& stop) {
  MapfSearchContext context(query, stop);
  auto distance = context.goalDistances(MapfSearchContext::Heuristic::kTrueDistance);
  if (static_cast<int>(distance.size()) < context.agentCount()) return context.timeUp();
  std::vector<int> starts, goals;
  for (int a = 0; a < context.agentCount(); ++a) {
    starts.push_back(context.start(a));
    goals.push_back(context.goal(a));
  }
  CbsSearch search(context.grid(), std::move(starts), std::move(goals), std::move(distance),
                   options_, context.deadline());
  const CbsOutcome outcome = search.run();
  MapfResult result;
  result.success = outcome.status == CbsOutcome::Status::kSolved;
  for (const auto& p : outcome.paths) result.paths.push_back(context.grid().toCells(p));
  const auto [message, gave_up] = failure(outcome);
  result.message = message;
  result.status = searchStatus(result.success, context.deadline(), gave_up);
  result.counters["ct_nodes"] = static_cast<double>(outcome.ct_nodes);
  result.counters["expansions"] = static_cast<double>(outcome.expansions);
  result.counters["low_level_calls"] = static_cast<double>(outcome.low_level_calls);
  result.counters["bypasses"] = static_cast<double>(outcome.bypasses);
  return context.finish(std::move(result));
}

}  // namespace cosim
