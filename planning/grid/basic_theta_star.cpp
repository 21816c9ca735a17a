#include "planning/grid/basic_theta_star.h"

#include "planning/grid/grid_any_angle_search.h"

namespace cosim {

GridPlanResult BasicThetaStar::solveGrid(const GridQuery& query, const StopToken& stop) {
  const StopToken clock(query.time_limit_s, stop);
  if (GridPlanResult rejected; gridQueryRejected(query, rejected)) return rejected;
  const GridSearchSpace space(
      *query.grid, resolveGridMoves(moves_, query.grid->is3D(), params_file_), query.segments);
  auto& nodes = work_.nodes;
  GridSearchCounters counters;
  return anyAngleSearch(
      query, space, work_, GridNodeTable<double>::State::Open, clock, counters,
      [](std::uint32_t, const Cell&, const GridOpenList<double>::Entry&) { return true; },
      [&](std::uint32_t u, const Cell&, std::uint32_t v, const Cell& vc,
          const GridSearchSpace::Move& m) {
        // ComputeCost: path 2 (from u's parent, if it sees v), else path 1 (through u).
        const std::uint32_t p = nodes.parent(u);
        if (p != u) {
          counters.los_checks += 1;
          if (space.lineOfSight(p, v)) {
            const Cell pc = space.cellOf(p);
            return AnyAngleCandidate{
                nodes.g(p) + euclideanDistance(vc.x - pc.x, vc.y - pc.y, vc.z - pc.z), p};
          }
        }
        return AnyAngleCandidate{nodes.g(u) + m.cost, u};
      });
}

}  // namespace cosim
