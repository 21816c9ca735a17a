#include "planning/mapf/reverse_resumable_astar.h"

namespace cosim {

ReverseResumableAStar::ReverseResumableAStar(const MapfGrid& grid, int goal, int start,
                                             const StopToken* deadline)
    : grid_(&grid),
      deadline_(deadline),
      goal_(goal),
      start_(start),
      g_(grid.cellCount(), kUnreachable),
      closed_(grid.cellCount(), 0) {
  if (!grid.free(goal)) return;
  g_[goal] = 0;
  open_.emplace(grid.lowerBound(goal, start), 0, goal);
}

int ReverseResumableAStar::distance(int cell) {
  if (!closed_[cell]) resumeUntilClosed(cell);
  if (closed_[cell]) return g_[cell];
  // Stopped by the deadline with cells left to expand: nothing is known to be unreachable.
  return open_.empty() ? kUnreachable : grid_->lowerBound(cell, goal_);
}

void ReverseResumableAStar::resumeUntilClosed(int target) {
  while (!open_.empty()) {
    const auto [f, minus_g, cell] = open_.top();
    open_.pop();
    if (closed_[cell] || -minus_g > g_[cell]) continue;  // stale entry
    if ((expansions_ & 1023) == 1023 && deadline_ && deadline_->expired()) {
      open_.emplace(f, minus_g, cell);  // not expanded: kept for a later resume
      return;
    }
    closed_[cell] = 1;
    ++expansions_;
    // Moves are symmetric (the corner rule does not depend on direction), so the forward
    // neighbours are also the reverse ones.
    for (const int n : grid_->neighbours(cell)) {
      const int g = g_[cell] + 1;
      if (closed_[n] || g >= g_[n]) continue;
      g_[n] = g;
      open_.emplace(g + grid_->lowerBound(n, start_), -g, n);
    }
    if (cell == target) return;
  }
}

}  // namespace cosim
