#include "planning/grid/lazy_theta_star.h"

#include <limits>

#include "planning/grid/grid_any_angle_search.h"

namespace cosim {

GridPlanResult LazyThetaStar::solveGrid(const GridQuery& query, const StopToken& stop) {
  using State = GridNodeTable<double>::State;
  const StopToken clock(query.time_limit_s, stop);
  if (GridPlanResult rejected; gridQueryRejected(query, rejected)) return rejected;
  const GridSearchSpace space(
      *query.grid, resolveGridMoves(moves_, query.grid->is3D(), params_file_), query.segments);
  auto& nodes = work_.nodes;
  const Cell gc = query.goal;
  GridSearchCounters counters;
  // State::Open: the parent link is assumed; State::OpenVerified: it has been checked (or
  // comes from SetVertex, whose parents are neighbours reached by legal moves).
  return anyAngleSearch(
      query, space, work_, State::OpenVerified, clock, counters,
      [&](std::uint32_t u, const Cell& c, const GridOpenList<double>::Entry& top) {
        if (nodes.state(u) != State::Open) return true;
        counters.los_checks += 1;
        if (space.lineOfSight(nodes.parent(u), u)) return true;
        // SetVertex: the best closed neighbour becomes the parent.
        double best = std::numeric_limits<double>::infinity();
        std::uint32_t best_parent = u;
        const std::uint32_t free = space.neighbourMask(u, c);
        for (const auto& m : space.moves()) {
          if (!space.moveAllowed(free, m, u, c)) continue;
          const std::uint32_t n = static_cast<std::uint32_t>(u + m.offset);
          if (nodes.seen(n) && nodes.closed(n) && nodes.g(n) + m.cost < best) {
            best = nodes.g(n) + m.cost;
            best_parent = n;
          }
        }
        nodes.set(u, best, best_parent, State::OpenVerified);
        if (variant_ == Variant::kExpandAtOnce || best <= top.g) return true;
        // The deviation described in the header: back into OPEN under the true key.
        work_.open.push({best + euclideanDistance(c.x - gc.x, c.y - gc.y, c.z - gc.z), best, u});
        counters.pushes += 1;
        return false;
      },
      [&](std::uint32_t u, const Cell&, std::uint32_t, const Cell& vc,
          const GridSearchSpace::Move&) {
        // ComputeCost without a line-of-sight check: path 2 is assumed.
        const std::uint32_t p = nodes.parent(u);
        const Cell pc = space.cellOf(p);
        return AnyAngleCandidate{
            nodes.g(p) + euclideanDistance(vc.x - pc.x, vc.y - pc.y, vc.z - pc.z), p};
      });
}

}  // namespace cosim
