#pragma once
// The search loop shared by A* and Dijkstra on a GridSearchSpace: best-first on f = g + h with
// a closed set and no re-opening (with a consistent heuristic a cell's g is final when it is
// expanded). Written for speed: flat arrays, O(1) set-up per query, one neighbour mask per
// expansion, exact integer costs, and lazy deletion: an improved cell is pushed again, and its
// outdated entries, having a larger f, come out after it and are skipped as closed.
//
// With a consistent heuristic (A* with weight 1, Dijkstra) the keys taken out never decrease,
// and OPEN is a radix heap; a weighted heuristic breaks that, and OPEN is a binary heap.
#include <cstdint>

#include "core/stop_token.h"
#include "planning/grid/grid_open_list.h"
#include "planning/grid/grid_radix_heap.h"
#include "planning/grid/grid_search_outcome.h"

namespace cosim {

struct BestFirstWorkspace {
  GridNodeTable<FixedCost> nodes;
  GridRadixHeap monotone_open;
  GridOpenList<FixedCost> open;
};

// h(dx, dy, dz) estimates, in FixedCost units, the remaining cost from a cell at offset
// (dx, dy, dz) from the goal; `consistent` says whether it is consistent (never decreases f
// along a move), which selects the radix heap.
template <class Heuristic>
GridSearchEnd bestFirstSearch(const GridSearchSpace& space, BestFirstWorkspace& w,
                              std::uint32_t start, std::uint32_t goal, Heuristic&& h,
                              bool consistent, const StopToken& deadline,
                              GridSearchCounters& counters) {
  using State = GridNodeTable<FixedCost>::State;
  auto& nodes = w.nodes;
  const Cell gc = space.cellOf(goal);
  nodes.begin(space.size());
  w.monotone_open.clear();
  w.open.clear();
  nodes.set(start, 0, start, State::Open);
  const Cell sc = space.cellOf(start);
  const FixedCost f0 = h(sc.x - gc.x, sc.y - gc.y, sc.z - gc.z);
  if (consistent)
    w.monotone_open.push({f0, start});
  else
    w.open.push({f0, 0, start});
  std::uint64_t expansions = 0, pushes = 1;
  GridSearchEnd end = GridSearchEnd::Exhausted;
  const auto& moves = space.moves();
  for (;;) {
    std::uint32_t u;
    if (consistent) {
      if (w.monotone_open.empty()) break;
      u = w.monotone_open.pop().cell;
    } else {
      if (w.open.empty()) break;
      u = w.open.pop().cell;
    }
    if (nodes.closed(u)) continue;  // outdated entry
    nodes.setState(u, State::Closed);
    if (u == goal) {
      end = GridSearchEnd::Found;
      break;
    }
    if ((++expansions & kDeadlinePollMask) == 0 && deadline.expired()) {
      end = GridSearchEnd::TimeLimit;
      break;
    }
    const FixedCost gu = nodes.g(u);
    const Cell c = space.cellOf(u);
    const std::uint32_t free = space.neighbourMask(u, c);
    for (const auto& m : moves) {
      if (!space.moveAllowed(free, m, u, c)) continue;
      const std::uint32_t v = static_cast<std::uint32_t>(u + m.offset);
      const FixedCost g = gu + m.fixed_cost;
      if (nodes.seen(v) && (nodes.closed(v) || nodes.g(v) <= g)) continue;
      nodes.set(v, g, u, State::Open);
      const FixedCost f = g + h(c.x + m.dx - gc.x, c.y + m.dy - gc.y, c.z + m.dz - gc.z);
      if (consistent)
        w.monotone_open.push({f, v});
      else
        w.open.push({f, g, v});
      ++pushes;
    }
  }
  counters.expansions += static_cast<double>(expansions + (end == GridSearchEnd::Found));
  counters.pushes += static_cast<double>(pushes);
  return end;
}

}  // namespace cosim
