#pragma once
// What Conflict-Based Search's low level is asked to respect (conflict_based_search.h): the
// constraints a constraint-tree branch puts on one agent, and the conflict avoidance table that
// breaks ties towards paths with fewer conflicts with the other agents (Sharon et al. 2015, §4.3).
#include <algorithm>
#include <cstdint>
#include <memory>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "planning/mapf/mapf_grid.h"
#include "planning/mapf/space_time_constraints.h"

namespace cosim::cbs {

using IdPath = std::vector<int>;  // grid cell ids by time, from the start to the arrival
using SharedPath = std::shared_ptr<const IdPath>;

// (time, cell or move key) packed into one key.
inline std::uint64_t timeKey(std::uint32_t what, int t) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(t)) << 32) | what;
}

// The cell of path `p` at time t (an arrived agent stays on its last cell).
inline int cellAt(const IdPath& p, int t) {
  return p[std::min<std::size_t>(static_cast<std::size_t>(t), p.size() - 1)];
}

// One constraint of the constraint tree: `agent` may not be at `cell` at time t (vertex), or may
// not move from `cell` to `to` between t and t + 1 (move).
struct Constraint {
  int agent = -1;
  bool move = false;
  int cell = 0, to = 0, t = 0;
};

// An agent's constraints, as its low-level search asks for them.
class AgentConstraints final : public SpaceTimeConstraints {
 public:
  void add(const Constraint& c);
  bool cellBlocked(int cell, int t) const override {
    return cells_.count(timeKey(static_cast<std::uint32_t>(cell), t)) != 0;
  }
  bool moveBlocked(int from, int to, int t) const override {
    return moves_.count({from, to, t}) != 0;
  }
  int lastBlockedTime(int cell) const override {
    const auto it = last_.find(cell);
    return it == last_.end() ? -1 : it->second;
  }
  int staticFrom() const override { return static_from_; }

 private:
  std::unordered_set<std::uint64_t> cells_;
  std::set<std::tuple<int, int, int>> moves_;
  std::unordered_map<int, int> last_;
  int static_from_ = 0;
};

// The conflict avoidance table: how many of the other agents' current paths a step hits.
class ConflictAvoidanceTable final : public SpaceTimeConflictCounter {
 public:
  // The paths of every agent but `skip` (missing paths are skipped too).
  ConflictAvoidanceTable(const MapfGrid& grid, const std::vector<SharedPath>& paths, int skip);
  int conflicts(int from, int to, int t) const override;
  int staticFrom() const override { return static_from_; }

 private:
  const MapfGrid* grid_;
  std::unordered_map<std::uint64_t, int> cells_, moves_;
  std::unordered_map<int, int> parked_from_;
  int static_from_ = 0;
};

}  // namespace cosim::cbs
