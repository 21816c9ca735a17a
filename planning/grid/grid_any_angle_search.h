#pragma once
// The search loop shared by Basic Theta* and Lazy Theta*: A*-style best-first on
// f = g + straight-line distance to the goal, over the grid's moves, where a relaxation may make
// a cell's parent any earlier cell (not only the neighbour it was reached from). The planners
// differ in two hooks: what happens when a cell is taken from OPEN (Lazy Theta*'s SetVertex) and
// how a neighbour's cost and parent are computed (ComputeCost).
#include <cstdint>

#include "core/stop_token.h"
#include "planning/grid/grid_distance.h"
#include "planning/grid/grid_open_list.h"
#include "planning/grid/grid_search_outcome.h"

namespace cosim {

struct AnyAngleWorkspace {
  GridNodeTable<double> nodes;
  GridOpenList<double> open;
};

// What ComputeCost proposes for a neighbour: its cost so far and its parent.
struct AnyAngleCandidate {
  double g;
  std::uint32_t parent;
};

// on_pop(u, c, entry) -> bool: called for every current entry taken from OPEN before the cell is
// closed; returning false means the cell was re-queued and must not be expanded now.
// compute_cost(u, c, v, vc, move) -> AnyAngleCandidate for neighbour v (cell vc) of u (cell c).
// `start_state` is the node-table state the start cell begins in.
template <class OnPop, class ComputeCost>
GridPlanResult anyAngleSearch(const GridQuery& query, const GridSearchSpace& space,
                              AnyAngleWorkspace& w, GridNodeTable<double>::State start_state,
                              const StopToken& clock, GridSearchCounters& counters, OnPop&& on_pop,
                              ComputeCost&& compute_cost) {
  using State = GridNodeTable<double>::State;
  auto& nodes = w.nodes;
  const std::uint32_t start = space.index(query.start), goal = space.index(query.goal);
  const Cell gc = query.goal;
  auto h = [&gc](const Cell& c) { return euclideanDistance(c.x - gc.x, c.y - gc.y, c.z - gc.z); };
  nodes.begin(space.size());
  w.open.clear();
  nodes.set(start, 0.0, start, start_state);
  w.open.push({h(query.start), 0.0, start});
  counters.pushes += 1;
  std::uint64_t expansions = 0;
  GridSearchEnd end = GridSearchEnd::Exhausted;
  while (!w.open.empty()) {
    const GridOpenList<double>::Entry top = w.open.pop();
    const std::uint32_t u = top.cell;
    if (nodes.closed(u) || top.g != nodes.g(u)) continue;  // outdated entry
    const Cell c = space.cellOf(u);
    if (!on_pop(u, c, top)) continue;
    nodes.setState(u, State::Closed);
    ++expansions;
    if (u == goal) {
      end = GridSearchEnd::Found;
      break;
    }
    if ((expansions & kDeadlinePollMask) == 0 && clock.expired()) {
      end = GridSearchEnd::TimeLimit;
      break;
    }
    const std::uint32_t free = space.neighbourMask(u, c);
    for (const auto& m : space.moves()) {
      if (!space.moveAllowed(free, m, u, c)) continue;
      const std::uint32_t v = static_cast<std::uint32_t>(u + m.offset);
      if (nodes.seen(v) && nodes.closed(v)) continue;
      const Cell vc{c.x + m.dx, c.y + m.dy, c.z + m.dz};
      const AnyAngleCandidate cand = compute_cost(u, c, v, vc, m);
      if (nodes.seen(v) && nodes.g(v) <= cand.g) continue;
      nodes.set(v, cand.g, cand.parent, State::Open);
      w.open.push({cand.g + h(vc), cand.g, v});
      counters.pushes += 1;
    }
  }
  counters.expansions = static_cast<double>(expansions);
  return gridSearchResult(space, nodes, start, goal, end, counters, clock, true);
}

}  // namespace cosim
