#include "planning/mapf/conflict_based_search.h"

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <queue>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "planning/mapf/mapf_grid.h"
#include "planning/mapf/reverse_resumable_astar.h"
#include "planning/mapf/space_time_astar.h"

namespace cosim {

namespace {

using IdPath = std::vector<int>;
using SharedPath = std::shared_ptr<const IdPath>;

std::uint64_t timeKey(std::uint32_t what, int t) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(t)) << 32) | what;
}

int cellAt(const IdPath& p, int t) {
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
  void add(const Constraint& c) {
    if (c.move) {
      moves_.insert({c.cell, c.to, c.t});
    } else {
      cells_.insert(timeKey(static_cast<std::uint32_t>(c.cell), c.t));
      auto [it, inserted] = last_.try_emplace(c.cell, c.t);
      if (!inserted) it->second = std::max(it->second, c.t);
    }
    static_from_ = std::max(static_from_, c.t + 1);
  }
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
  ConflictAvoidanceTable(const MapfGrid& grid, const std::vector<SharedPath>& paths, int skip)
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
  int conflicts(int from, int to, int t) const override {
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
  int staticFrom() const override { return static_from_; }

 private:
  const MapfGrid* grid_;
  std::unordered_map<std::uint64_t, int> cells_, moves_;
  std::unordered_map<int, int> parked_from_;
  int static_from_ = 0;
};

struct Conflict {
  int a = -1, b = -1, t = 0;
  bool move = false;
  int cell = 0;                                    // vertex conflict
  int a_from = 0, a_to = 0, b_from = 0, b_to = 0;  // move conflict (between t and t + 1)
};

// Finds the conflicts between the paths (same rules as MapfGrid::moveKey: vertex, swap and
// crossing diagonals; agents stay on their goals); returns their number and the earliest.
class ConflictFinder {
 public:
  explicit ConflictFinder(const MapfGrid& grid)
      : cell_owner_(grid.cellCount()),
        cell_stamp_(grid.cellCount(), -1),
        move_owner_(static_cast<std::size_t>(grid.cellCount()) * 4),
        move_stamp_(move_owner_.size(), -1),
        grid_(&grid) {}

  // All conflicts, in time order, up to `keep` of them in `list` (if given); returns the count.
  int find(const std::vector<SharedPath>& paths, std::vector<Conflict>* list = nullptr,
           std::size_t keep = 64) {
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

 private:
  std::vector<int> cell_owner_, cell_stamp_, move_owner_, move_stamp_;
  const MapfGrid* grid_;
  int stamp_ = 0;
};

struct TreeNode {
  int parent = -1;
  Constraint constraint;  // the one this node added (none at the root)
  std::vector<SharedPath> paths;
  long cost = 0;
  int conflicts = 0;
};

long pathCost(const IdPath& p) {
  return static_cast<long>(p.size()) - 1;
}

// The cells every path of length `cost` from start to goal that respects `constraints` must
// visit: result[t] is the only cell of the MDD's level t (Sharon et al., "The increasing cost
// tree search for optimal multi-agent pathfinding", AIJ 2013), or -1 if the level is wider.
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

}  // namespace

MapfResult ConflictBasedSearch::solve(const MapfQuery& query) {
  const StopToken deadline(query.time_limit_s, query.stop);
  const MapfInstance& inst = *query.instance;
  const MapfGrid grid(inst.grid, inst.connectivity);
  const int n = inst.agentCount();
  MapfResult result;

  std::vector<std::unique_ptr<ReverseResumableAStar>> distance;
  for (int a = 0; a < n; ++a) {
    if (deadline.expired()) {
      result.message = "time limit reached";
      result.status = expiredStatus(deadline);
      result.time_ms = deadline.elapsedMs();
      return result;
    }
    distance.push_back(std::make_unique<ReverseResumableAStar>(grid, grid.id(inst.goals[a]),
                                                               grid.id(inst.starts[a]), &deadline));
  }
  SpaceTimeAStar search(grid);
  ConflictFinder finder(grid);
  long expansions = 0, low_level_calls = 0, bypasses = 0;
  bool budget_hit = false;

  std::vector<TreeNode> tree(1);  // the constraint tree; node 0 is the root
  // The constraints on `agent` along the branch from the root to node `id`.
  const auto constraintsOf = [&](int id, int agent) {
    AgentConstraints constraints;
    for (int k = id; k > 0; k = tree[k].parent)
      if (tree[k].constraint.agent == agent) constraints.add(tree[k].constraint);
    return constraints;
  };
  const auto replan = [&](int agent, const AgentConstraints& constraints,
                          const std::vector<SharedPath>& paths) {
    const ConflictAvoidanceTable avoid(grid, paths, agent);
    SpaceTimeRequest request;
    request.start = grid.id(inst.starts[agent]);
    request.goal = grid.id(inst.goals[agent]);
    request.constraints = &constraints;
    request.conflict_counter = &avoid;
    request.heuristic = distance[agent].get();
    request.max_expansions = options_.max_expansions;
    request.deadline = &deadline;
    const SpaceTimePlan plan = search.plan(request);
    expansions += plan.expansions;
    ++low_level_calls;
    budget_hit = budget_hit || plan.out_of_budget;
    return plan;
  };
  // gave_up: why the search ended without a solution when neither the deadline nor a stop did.
  const auto finish = [&](const std::string& message, PlannerStatus gave_up) {
    result.message = message;
    result.status = searchStatus(result.success, deadline, gave_up);
    result.counters["ct_nodes"] = static_cast<double>(tree.size());
    result.counters["expansions"] = static_cast<double>(expansions);
    result.counters["low_level_calls"] = static_cast<double>(low_level_calls);
    result.counters["bypasses"] = static_cast<double>(bypasses);
    result.time_ms = deadline.elapsedMs();
    return result;
  };

  tree[0].paths.resize(n);
  for (int a = 0; a < n; ++a) {
    if (deadline.expired()) return finish("time limit reached", PlannerStatus::Timeout);
    const SpaceTimePlan plan = replan(a, AgentConstraints(), tree[0].paths);
    if (!plan.found)
      return finish(budget_hit ? "time limit reached"
                               : "goal of agent " + std::to_string(a) + " is unreachable",
                    budget_hit ? PlannerStatus::LimitReached : PlannerStatus::NoSolution);
    tree[0].paths[a] = std::make_shared<const IdPath>(plan.cells);
    tree[0].cost += pathCost(plan.cells);
  }
  tree[0].conflicts = finder.find(tree[0].paths);

  // (sum of costs, conflicts, node): best-first, ties towards fewer conflicts, then older nodes.
  using Entry = std::tuple<long, int, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  open.emplace(tree[0].cost, tree[0].conflicts, 0);
  std::string failure = "no solution (constraint tree exhausted)";
  PlannerStatus gave_up = PlannerStatus::NoSolution;
  // Cardinal conflicts first (Boyarski et al., "ICBS: Improved Conflict-Based Search", IJCAI
  // 2015): a conflict is cardinal for an agent when all its optimal paths under its constraints
  // pass through it (MDD width 1 there, or the agent is already parked on the cell), so splitting
  // on it raises the cost of both children and the lower bound grows fastest.
  const auto choose = [&](int id, const std::vector<Conflict>& list) {
    std::map<int, std::vector<int>> single;  // agent -> its MDD's width-1 cells by time
    const auto cardinalFor = [&](int agent, const Conflict& c, bool first_side) {
      const IdPath& path = *tree[id].paths[agent];
      const int cost = static_cast<int>(path.size()) - 1;
      if (!c.move && c.t >= cost) return true;  // parked on its goal: must arrive later
      auto it = single.find(agent);
      if (it == single.end())
        it = single
                 .emplace(agent, mddSingletons(grid, path.front(), path.back(), cost,
                                               constraintsOf(id, agent), *distance[agent]))
                 .first;
      const std::vector<int>& at = it->second;
      if (!c.move) return at[c.t] == c.cell;
      const int from = first_side ? c.a_from : c.b_from, to = first_side ? c.a_to : c.b_to;
      return c.t + 1 <= cost && at[c.t] == from && at[c.t + 1] == to;
    };
    int best = 0, best_rank = -1;
    for (std::size_t i = 0; i < list.size() && best_rank < 2; ++i) {
      const int rank = static_cast<int>(cardinalFor(list[i].a, list[i], true)) +
                       static_cast<int>(cardinalFor(list[i].b, list[i], false));
      if (rank > best_rank) best_rank = rank, best = static_cast<int>(i);
    }
    return list[best];
  };
  while (!open.empty()) {
    const int id = std::get<2>(open.top());
    open.pop();
    std::vector<Conflict> conflicts;
    if (finder.find(tree[id].paths, &conflicts) == 0) {
      result.success = true;
      for (const auto& p : tree[id].paths) result.paths.push_back(grid.toCells(*p));
      failure.clear();
      break;
    }
    if (deadline.expired()) {
      failure = "time limit reached";
      break;
    }
    if (static_cast<long>(tree.size()) + 2 > options_.max_nodes) {
      failure = "constraint-tree node limit (max_nodes) reached";
      gave_up = PlannerStatus::LimitReached;
      break;
    }
    const Conflict conflict = choose(id, conflicts);
    std::vector<TreeNode> children;
    bool bypassed = false;
    for (int side = 0; side < 2 && !bypassed; ++side) {
      Constraint added;
      added.agent = side == 0 ? conflict.a : conflict.b;
      added.t = conflict.t;
      added.move = conflict.move;
      if (conflict.move) {
        added.cell = side == 0 ? conflict.a_from : conflict.b_from;
        added.to = side == 0 ? conflict.a_to : conflict.b_to;
      } else {
        added.cell = conflict.cell;
      }
      AgentConstraints constraints = constraintsOf(id, added.agent);
      constraints.add(added);
      const SpaceTimePlan plan = replan(added.agent, constraints, tree[id].paths);
      if (!plan.found) continue;  // this branch has no solution (or ran out of budget)
      TreeNode child;
      child.parent = id;
      child.constraint = added;
      child.paths = tree[id].paths;
      child.cost = tree[id].cost - pathCost(*child.paths[added.agent]) + pathCost(plan.cells);
      child.paths[added.agent] = std::make_shared<const IdPath>(plan.cells);
      child.conflicts = finder.find(child.paths);
      if (options_.bypass && child.cost == tree[id].cost && child.conflicts < tree[id].conflicts) {
        // Bypass: the parent's constraints admit this path too; take it and look again.
        tree[id].paths = std::move(child.paths);
        tree[id].conflicts = child.conflicts;
        open.emplace(tree[id].cost, tree[id].conflicts, id);
        ++bypasses;
        bypassed = true;
        break;
      }
      children.push_back(std::move(child));
    }
    if (bypassed) continue;
    for (auto& child : children) {
      open.emplace(child.cost, child.conflicts, static_cast<int>(tree.size()));
      tree.push_back(std::move(child));
    }
  }
  if (!result.success && budget_hit && failure.rfind("no solution", 0) == 0) {
    failure = "low-level search limit reached";
    gave_up = PlannerStatus::LimitReached;
  }
  return finish(failure, gave_up);
}

}  // namespace cosim
