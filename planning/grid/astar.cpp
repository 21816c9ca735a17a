#include "planning/grid/astar.h"

#include "planning/grid/grid_distance.h"

namespace cosim {

GridPlanResult AStar::solveGrid(const GridQuery& query, const StopToken& stop) {
  const StopToken clock(query.time_limit_s, stop);
  if (GridPlanResult rejected; gridQueryRejected(query, rejected)) return rejected;
  const GridMoves moves = resolveGridMoves(options_.moves, query.grid->is3D(), params_file_);
  const GridSearchSpace space(*query.grid, moves, query.segments);
  const bool axis_only = moves.connectivity == 4 || moves.connectivity == 6;
  const double w = options_.heuristic_weight;
  auto weighted = [w](FixedCost h) {
    return w == 1.0 ? h : static_cast<FixedCost>(w * static_cast<double>(h));
  };
  GridSearchCounters counters;
  const std::uint32_t start = space.index(query.start), goal = space.index(query.goal);
  const GridSearchEnd end =
      axis_only ? bestFirstSearch(
                      space, work_, start, goal,
                      [&](int dx, int dy, int dz) {
                        return weighted(manhattanDistanceFixed(dx, dy, dz, kFixedStraight));
                      },
                      w == 1.0, clock, counters)
                : bestFirstSearch(
                      space, work_, start, goal,
                      [&](int dx, int dy, int dz) {
                        return weighted(octileDistanceFixed(
                            dx, dy, dz, kFixedStraight, kFixedFaceDiagonal, kFixedBodyDiagonal));
                      },
                      w == 1.0, clock, counters);
  return gridSearchResult(space, work_.nodes, start, goal, end, counters, clock, false);
}

GridPlanResult planAStar(const OccupancyGrid& grid, const Cell& start, const Cell& goal,
                         const GridMoves& moves, double time_limit_s) {
  AStar astar(AStar::Options{moves, 1.0});
  GridQuery q;
  q.grid = &grid;
  q.start = start;
  q.goal = goal;
  q.time_limit_s = time_limit_s;
  return astar.solveGrid(q, StopToken::untimed());
}

}  // namespace cosim
