#include "planning/grid/grid_search_outcome.h"

#include <tuple>

namespace cosim {

namespace {
std::string cellText(const Cell& c) {
  std::string s = "(";  // appended piecewise: GCC 12 warns falsely on "(" + std::string
  s += std::to_string(c.x) + "," + std::to_string(c.y) + "," + std::to_string(c.z) + ")";
  return s;
}
}  // namespace

namespace {
// The status and message of a query that cannot be searched; status Unknown if it can be.
std::pair<PlannerStatus, std::string> gridQueryProblem(const GridQuery& q) {
  if (q.grid == nullptr) return {PlannerStatus::InvalidProblem, "no grid given"};
  if (!q.grid->inside(q.start))
    return {PlannerStatus::InvalidStart, "start cell " + cellText(q.start) + " is outside the grid"};
  if (!q.grid->inside(q.goal))
    return {PlannerStatus::InvalidGoal, "goal cell " + cellText(q.goal) + " is outside the grid"};
  if (q.grid->blocked(q.start))
    return {PlannerStatus::InvalidStart, "start cell " + cellText(q.start) + " is blocked"};
  if (q.grid->blocked(q.goal))
    return {PlannerStatus::InvalidGoal, "goal cell " + cellText(q.goal) + " is blocked"};
  return {PlannerStatus::Unknown, ""};
}
}  // namespace

bool gridQueryRejected(const GridQuery& query, GridPlanResult& result) {
  result = GridPlanResult();
  std::tie(result.status, result.message) = gridQueryProblem(query);
  return !result.message.empty();
}

GridPlanResult gridSearchResult(const GridSearchSpace& space,
                                const std::vector<std::uint32_t>& goal_to_start, GridSearchEnd end,
                                const GridSearchCounters& counters, const StopToken& clock,
                                bool any_angle) {
  GridPlanResult r;
  r.counters["expansions"] = counters.expansions;
  if (any_angle) r.counters["los_checks"] = counters.los_checks;
  r.counters["heap_pushes"] = counters.pushes;
  if (end == GridSearchEnd::Found) {
    for (auto it = goal_to_start.rbegin(); it != goal_to_start.rend(); ++it)
      r.cells.push_back(space.cellOf(*it));
    r.length = gridPathLength(r.cells);
    r.success = true;
    r.status = searchStatus(true, clock, PlannerStatus::NoSolution);
  } else if (end == GridSearchEnd::TimeLimit) {
    r.status = expiredStatus(clock);
    r.message = "time limit";
  } else {
    r.status = PlannerStatus::NoSolution;
    r.message = "no path";
    r.exhausted = true;
  }
  r.time_ms = clock.elapsedMs();
  return r;
}

}  // namespace cosim
