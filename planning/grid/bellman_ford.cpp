#include "planning/grid/bellman_ford.h"

#include "planning/grid/grid_search_outcome.h"

namespace cosim {

GridPlanResult BellmanFord::solveGrid(const GridQuery& query, const StopToken& stop) {
  using State = GridNodeTable<FixedCost>::State;
  const StopToken clock(query.time_limit_s, stop);
  if (GridPlanResult rejected; gridQueryRejected(query, rejected)) return rejected;
  const GridSearchSpace space(
      *query.grid, resolveGridMoves(moves_, query.grid->is3D(), params_file_), query.segments);
  const std::uint32_t start = space.index(query.start), goal = space.index(query.goal);
  // State::Open marks a cell waiting in the queue, State::Closed a labelled cell not in it.
  nodes_.begin(space.size());
  if (queue_.size() < space.size()) queue_.resize(space.size());
  const std::size_t capacity = queue_.size();
  std::size_t head = 0, count = 0;
  auto enqueue = [&](std::uint32_t v) { queue_[(head + count++) % capacity] = v; };

  nodes_.set(start, 0, start, State::Open);
  enqueue(start);
  GridSearchCounters counters;
  std::uint64_t scans = 0;
  GridSearchEnd end = GridSearchEnd::Exhausted;
  while (count > 0) {
    const std::uint32_t u = queue_[head];
    head = (head + 1) % capacity;
    --count;
    nodes_.setState(u, State::Closed);
    if ((++scans & kDeadlinePollMask) == 0 && clock.expired()) {
      end = GridSearchEnd::TimeLimit;
      break;
    }
    const FixedCost gu = nodes_.g(u);
    const Cell c = space.cellOf(u);
    const std::uint32_t free = space.neighbourMask(u, c);
    for (const auto& m : space.moves()) {
      if (!space.moveAllowed(free, m, u, c)) continue;
      const std::uint32_t v = static_cast<std::uint32_t>(u + m.offset);
      const FixedCost g = gu + m.fixed_cost;
      if (nodes_.seen(v) && nodes_.g(v) <= g) continue;
      const bool queued = nodes_.seen(v) && !nodes_.closed(v);
      nodes_.set(v, g, u, State::Open);
      if (!queued) {
        enqueue(v);
        counters.pushes += 1;
      }
    }
  }
  counters.expansions = static_cast<double>(scans);
  if (end != GridSearchEnd::TimeLimit && nodes_.seen(goal)) end = GridSearchEnd::Found;
  return gridSearchResult(space, nodes_, start, goal, end, counters, clock, false);
}

}  // namespace cosim
