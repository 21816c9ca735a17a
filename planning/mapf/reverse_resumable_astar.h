#pragma once
// Reverse Resumable A* (Silver 2005, "Cooperative Pathfinding", §4; seed 004 §3.4): the exact
// obstacle-aware distance to an agent's goal, ignoring other agents, computed on demand. An A*
// search runs backwards from the goal towards the agent's start; when a cell that is not yet
// closed is queried, the same search resumes until that cell is closed. With unit step costs and
// a consistent heuristic, every closed cell's g is its true distance to the goal.
#include <cstdint>
#include <queue>
#include <tuple>
#include <vector>

#include "core/stop_token.h"
#include "planning/mapf/goal_distance.h"
#include "planning/mapf/mapf_grid.h"

namespace cosim {

class ReverseResumableAStar final : public GoalDistance {
 public:
  // With a `deadline`, a resumed search stops when it expires (one resume could otherwise cover
  // the whole map, seconds on the largest ones).
  ReverseResumableAStar(const MapfGrid& grid, int goal, int start,
                        const StopToken* deadline = nullptr);

  // True distance from `cell` to the goal, or kUnreachable. Past the deadline, for a cell not yet
  // closed: the grid's lower bound (still admissible, so searches stay correct; the planner sees
  // the expired deadline itself and stops).
  int distance(int cell) override;
  long expansions() const { return expansions_; }

 private:
  // Expands until `target` is closed or the open list is empty.
  void resumeUntilClosed(int target);

  const MapfGrid* grid_;
  const StopToken* deadline_;
  int goal_, start_;
  std::vector<int> g_;
  std::vector<std::uint8_t> closed_;
  // (f, -g, cell): smallest f first, deeper nodes first on ties, then the smaller cell id.
  using Entry = std::tuple<int, int, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open_;
  long expansions_ = 0;
};

}  // namespace cosim
