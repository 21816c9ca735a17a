#include "planning/grid/dijkstra.h"

#include "planning/grid/grid_best_first_search.h"

namespace cosim {

GridPlanResult Dijkstra::solveGrid(const GridQuery& query, const StopToken& stop) {
  const StopToken clock(query.time_limit_s, stop);
  if (GridPlanResult rejected; gridQueryRejected(query, rejected)) return rejected;
  const GridSearchSpace space(
      *query.grid, resolveGridMoves(moves_, query.grid->is3D(), params_file_), query.segments);
  GridSearchCounters counters;
  const std::uint32_t start = space.index(query.start), goal = space.index(query.goal);
  const GridSearchEnd end = bestFirstSearch(
      space, work_, start, goal, [](int, int, int) { return FixedCost(0); }, true, clock, counters);
  return gridSearchResult(space, work_.nodes, start, goal, end, counters, clock, false);
}

}  // namespace cosim
