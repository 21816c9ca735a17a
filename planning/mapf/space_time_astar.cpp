#include "planning/mapf/space_time_astar.h"

#include <algorithm>
#include <functional>
#include <queue>
#include <tuple>
#include <unordered_map>

namespace cosim {

namespace {

struct SpaceTimeNode {
  int cell, t, g, conflicts, parent;
};

struct StateRecord {
  int g, conflicts;
  bool closed;
};

std::uint64_t stateKey(int cell, int t) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(t)) << 32) |
         static_cast<std::uint32_t>(cell);
}

}  // namespace

SpaceTimePlan SpaceTimeAStar::plan(const SpaceTimeRequest& r) {
  SpaceTimePlan out;
  const SpaceTimeConstraints& blocked = *r.constraints;
  const bool windowed = r.window > 0;
  const int t_end = r.start_time + r.window;
  const int goal_last = blocked.lastBlockedTime(r.goal);
  if (!windowed && goal_last == SpaceTimeConstraints::kForever) return out;
  if (blocked.cellBlocked(r.start, r.start_time)) return out;
  if (r.heuristic->distance(r.start) >= GoalDistance::kUnreachable) return out;

  // Beyond `horizon` nothing the search looks at changes, so (cell, t) and (cell, horizon) are
  // the same state; the earlier arrival at it is the better one.
  int horizon = std::max(blocked.staticFrom(), r.start_time);
  if (r.conflict_counter) horizon = std::max(horizon, r.conflict_counter->staticFrom());
  const auto mergedTime = [&](int t) { return windowed ? t : std::min(t, horizon); };

  std::vector<SpaceTimeNode> nodes;
  std::unordered_map<std::uint64_t, StateRecord> states;
  states.reserve(4096);
  // (f, soft conflicts, -t, node): lowest f, then fewest conflicts, then deepest, then oldest.
  using Entry = std::tuple<int, int, int, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;

  nodes.push_back({r.start, r.start_time, 0, 0, -1});
  states[stateKey(r.start, mergedTime(r.start_time))] = {0, 0, false};
  open.emplace(r.heuristic->distance(r.start), 0, -r.start_time, 0);

  while (!open.empty()) {
    const int index = std::get<3>(open.top());
    open.pop();
    const SpaceTimeNode node = nodes[index];
    StateRecord& record = states[stateKey(node.cell, mergedTime(node.t))];
    if (record.closed || node.g > record.g ||
        (node.g == record.g && node.conflicts > record.conflicts))
      continue;  // stale entry
    record.closed = true;

    const bool done = windowed ? node.t == t_end : (node.cell == r.goal && node.t > goal_last);
    if (done) {
      out.found = true;
      out.cost = node.g;
      out.conflicts = node.conflicts;
      for (int i = index; i >= 0; i = nodes[i].parent) out.cells.push_back(nodes[i].cell);
      std::reverse(out.cells.begin(), out.cells.end());
      break;
    }
    if (++out.expansions > r.max_expansions ||
        (r.deadline && (out.expansions & 255) == 0 && r.deadline->expired())) {
      out.out_of_budget = true;
      break;
    }

    const int nt = node.t + 1;
    const auto tryStep = [&](int next) {
      if (blocked.cellBlocked(next, nt)) return;
      if (next != node.cell && blocked.moveBlocked(node.cell, next, node.t)) return;
      const int h = r.heuristic->distance(next);
      if (h >= GoalDistance::kUnreachable) return;
      // Silver §5: in the window, an agent resting on its goal costs nothing.
      const int step_cost = (windowed && next == r.goal && node.cell == r.goal) ? 0 : 1;
      const int g = node.g + step_cost;
      const int conflicts =
          node.conflicts +
          (r.conflict_counter ? r.conflict_counter->conflicts(node.cell, next, node.t) : 0);
      const auto [it, inserted] =
          states.try_emplace(stateKey(next, mergedTime(nt)), StateRecord{g, conflicts, false});
      if (!inserted) {
        StateRecord& s = it->second;
        if (s.closed || g > s.g || (g == s.g && conflicts >= s.conflicts)) return;
        s.g = g;
        s.conflicts = conflicts;
      }
      nodes.push_back({next, nt, g, conflicts, index});
      open.emplace(g + h, conflicts, -nt, static_cast<int>(nodes.size()) - 1);
    };
    tryStep(node.cell);  // wait
    for (const int next : grid_->neighbours(node.cell)) tryStep(next);
  }
  return out;
}

}  // namespace cosim
