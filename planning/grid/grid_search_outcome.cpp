#include "planning/grid/grid_search_outcome.h"

namespace cosim {

namespace {
std::string cellText(const Cell& c) {
  std::string s = "(";  // appended piecewise: GCC 12 warns falsely on "(" + std::string
  s += std::to_string(c.x) + "," + std::to_string(c.y) + "," + std::to_string(c.z) + ")";
  return s;
}
}  // namespace

namespace {
std::string gridQueryProblem(const GridQuery& q) {
  if (q.grid == nullptr) return "no grid given";
  if (!q.grid->inside(q.start)) return "start cell " + cellText(q.start) + " is outside the grid";
  if (!q.grid->inside(q.goal)) return "goal cell " + cellText(q.goal) + " is outside the grid";
  if (q.grid->blocked(q.start)) return "start cell " + cellText(q.start) + " is blocked";
  if (q.grid->blocked(q.goal)) return "goal cell " + cellText(q.goal) + " is blocked";
  return "";
}
}  // namespace

bool gridQueryRejected(const GridQuery& query, GridPlanResult& result) {
  result = GridPlanResult();
  result.message = gridQueryProblem(query);
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
  } else {
    r.message = end == GridSearchEnd::TimeLimit ? "time limit" : "no path";
  }
  r.time_ms = clock.elapsedMs();
  return r;
}

}  // namespace cosim
