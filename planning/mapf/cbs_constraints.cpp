#include "planning/mapf/cbs_constraints.h"

namespace cosim::cbs {

void AgentConstraints::add(const Constraint& c) {
  if (c.move) {
    moves_.insert({c.cell, c.to, c.t});
  } else {
    cells_.insert(timeKey(static_cast<std::uint32_t>(c.cell), c.t));
    auto [it, inserted] = last_.try_emplace(c.cell, c.t);
    if (!inserted) it->second = std::max(it->second, c.t);
  }
  static_from_ = std::max(static_from_, c.t + 1);
}

ConflictAvoidanceTable::ConflictAvoidanceTable(const MapfGrid& grid,
                                               const std::vector<SharedPath>& paths, int skip)
    : grid_(&grid) {
  for (std::size_t b = 0; b < paths.size(); ++b) {
    if (static_cast<int>(b) == skip || !paths[b]) continue;
    const IdPath& p = *paths[b];
    const int arrival = static_cast<int>(p.size()) - 1;
    for (int t = 0; t < arrival; ++t) {
      ++cells_[timeKey(static_cast<std::uint32_t>(p[t]), t)];
      if (p[t + 1] != p[t]) ++moves_[timeKey(grid.moveKey(p[t], p[t + 1]), t)];
    }
    parked_from_[p.back()] = arrival;
    static_from_ = std::max(static_from_, arrival + 1);
  }
}

int ConflictAvoidanceTable::conflicts(int from, int to, int t) const {
  int count = 0;
  if (const auto it = cells_.find(timeKey(static_cast<std::uint32_t>(to), t + 1));
      it != cells_.end())
    count += it->second;
  if (const auto it = parked_from_.find(to); it != parked_from_.end() && it->second <= t + 1)
    ++count;
  if (from != to)
    if (const auto it = moves_.find(timeKey(grid_->moveKey(from, to), t)); it != moves_.end())
      count += it->second;
  return count;
}

}  // namespace cosim::cbs
