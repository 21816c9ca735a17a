#include "planning/mapf/cbs_conflicts.h"

#include <algorithm>

namespace cosim::cbs {

ConflictFinder::ConflictFinder(const MapfGrid& grid)
    : cell_owner_(grid.cellCount()),
      cell_stamp_(grid.cellCount(), -1),
      move_owner_(static_cast<std::size_t>(grid.cellCount()) * 4),
      move_stamp_(move_owner_.size(), -1),
      grid_(&grid) {}

int ConflictFinder::find(const std::vector<SharedPath>& paths, std::vector<Conflict>* list,
                         std::size_t keep) {
  std::size_t horizon = 1;
  for (const auto& p : paths) horizon = std::max(horizon, p->size());
  int count = 0;
  if (list) list->clear();
  const auto note = [&](const Conflict& c) {
    ++count;
    if (list && list->size() < keep) list->push_back(c);
  };
  for (int t = 0; t < static_cast<int>(horizon); ++t) {
    ++stamp_;
    for (int i = 0; i < static_cast<int>(paths.size()); ++i) {
      const int c = cellAt(*paths[i], t);
      if (cell_stamp_[c] == stamp_) {
        Conflict k;
        k.a = cell_owner_[c], k.b = i, k.t = t, k.cell = c;
        note(k);
      } else {
        cell_stamp_[c] = stamp_, cell_owner_[c] = i;
      }
    }
    for (int i = 0; i < static_cast<int>(paths.size()); ++i) {
      const int from = cellAt(*paths[i], t), to = cellAt(*paths[i], t + 1);
      if (from == to) continue;
      const std::uint32_t key = grid_->moveKey(from, to);
      if (move_stamp_[key] != stamp_) {
        move_stamp_[key] = stamp_, move_owner_[key] = i;
        continue;
      }
      Conflict k;
      k.a = move_owner_[key], k.b = i, k.t = t, k.move = true;
      k.a_from = cellAt(*paths[k.a], t), k.a_to = cellAt(*paths[k.a], t + 1);
      k.b_from = from, k.b_to = to;
      note(k);
    }
  }
  return count;
}

std::vector<int> mddSingletons(const MapfGrid& grid, int start, int goal, int cost,
                               const SpaceTimeConstraints& constraints, GoalDistance& distance) {
  const auto allowed = [&](int from, int to, int t) {  // step from t to t + 1
    return !constraints.cellBlocked(to, t + 1) &&
           (from == to || !constraints.moveBlocked(from, to, t));
  };
  std::vector<std::vector<int>> level(cost + 1);
  level[0] = {start};
  for (int t = 0; t < cost; ++t) {
    for (const int c : level[t]) {
      const auto add = [&](int next) {
        if (allowed(c, next, t) && distance.distance(next) <= cost - (t + 1))
          level[t + 1].push_back(next);
      };
      add(c);
      for (const int next : grid.neighbours(c)) add(next);
    }
    std::sort(level[t + 1].begin(), level[t + 1].end());
    level[t + 1].erase(std::unique(level[t + 1].begin(), level[t + 1].end()), level[t + 1].end());
  }
  // Backwards: keep the cells from which the goal is still reached at `cost`.
  level[cost].assign(1, goal);
  for (int t = cost - 1; t >= 0; --t) {
    const auto& next_level = level[t + 1];
    const auto inNext = [&](int c) {
      return std::binary_search(next_level.begin(), next_level.end(), c);
    };
    std::vector<int> kept;
    for (const int c : level[t]) {
      bool reaches = inNext(c) && allowed(c, c, t);
      for (const int next : grid.neighbours(c))
        reaches = reaches || (inNext(next) && allowed(c, next, t));
      if (reaches) kept.push_back(c);
    }
    level[t] = std::move(kept);
  }
  std::vector<int> single(cost + 1, -1);
  for (int t = 0; t <= cost; ++t)
    if (level[t].size() == 1) single[t] = level[t][0];
  return single;
}

}  // namespace cosim::cbs
