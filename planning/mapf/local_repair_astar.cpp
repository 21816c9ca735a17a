#include "planning/mapf/local_repair_astar.h"

#include <algorithm>
#include <cstdlib>
#include <random>

#include "planning/mapf/mapf_search_context.h"
#include "planning/mapf/spatial_astar.h"
#include "planning/mapf/step_arbiter.h"

namespace cosim {

MapfResult LocalRepairAStar::solve(const MapfQuery& query, const StopToken& stop) {
  MapfSearchContext context(query, stop);
  const StopToken& deadline = context.deadline();
  const MapfGrid& grid = context.grid();
  const int n = context.agentCount();
  const int max_steps = options_.max_steps > 0 ? options_.max_steps : grid.cellCount();
  std::mt19937_64 rng(context.seed());
  MapfResult result;

  std::vector<int> start(n), goal(n), replans(n, 0);
  std::vector<std::vector<int>> route(n);
  std::vector<std::size_t> next(n, 1);  // route[a][next[a]] is the next cell to enter
  long expansions = 0, total_replans = 0;
  for (int a = 0; a < n; ++a) {
    start[a] = context.start(a);
    goal[a] = context.goal(a);
    SpatialAStarRequest request{start[a], goal[a], nullptr, 0.0, nullptr, &deadline};
    const SpatialAStarResult path = spatialAStar(grid, request);
    expansions += path.expansions;
    if (path.cells.empty()) return context.unreachable(a);
    route[a] = path.cells;
  }

  StepArbiter arbiter(grid, start);
  std::vector<std::uint8_t> robots_near(grid.cellCount(), 0);
  while (!arbiter.finished(goal, max_steps, deadline, result)) {
    arbiter.beginStep();
    for (int a = 0; a < n; ++a) {
      const int here = arbiter.positions()[a];
      if (here == goal[a]) continue;  // arrived agents stay
      if (arbiter.tryMove(a, route[a][next[a]])) {
        ++next[a];
        continue;
      }
      // The next step is blocked: repair the route around the robots close by.
      const Cell c = grid.cell(here);
      std::vector<int> marked;
      for (int b = 0; b < n; ++b) {
        const Cell o = grid.cell(arbiter.positions()[b]);
        if (b != a && std::max(std::abs(o.x - c.x), std::abs(o.y - c.y)) <= options_.local_radius) {
          robots_near[arbiter.positions()[b]] = 1;
          marked.push_back(arbiter.positions()[b]);
        }
      }
      ++replans[a];
      ++total_replans;
      SpatialAStarRequest request{here, goal[a],  &robots_near, options_.agitation * replans[a],
                                  &rng, &deadline};
      const SpatialAStarResult repaired = spatialAStar(grid, request);
      expansions += repaired.expansions;
      for (const int m : marked) robots_near[m] = 0;
      if (repaired.cells.size() < 2) continue;  // boxed in (or goal occupied): wait
      route[a] = repaired.cells;
      next[a] = 1;
      if (arbiter.tryMove(a, route[a][1])) next[a] = 2;
    }
    arbiter.commitStep();
  }
  arbiter.storePaths(result);
  result.counters["expansions"] = static_cast<double>(expansions);
  result.counters["replans"] = static_cast<double>(total_replans);
  return context.finish(std::move(result));
}

}  // namespace cosim
