#include "planning/mapf/cbs_search.h"

#include <map>

namespace cosim {

using cbs::AgentConstraints;
using cbs::Conflict;
using cbs::Constraint;
using cbs::IdPath;

namespace {

long pathCost(const IdPath& p) {
  return static_cast<long>(p.size()) - 1;
}

}  // namespace

CbsSearch::CbsSearch(const MapfGrid& grid, std::vector<int> starts, std::vector<int> goals,
                     std::vector<std::unique_ptr<GoalDistance>> distance,
                     const ConflictBasedSearchOptions& options, const StopToken& deadline)
    : grid_(grid),
      starts_(std::move(starts)),
      goals_(std::move(goals)),
      distance_(std::move(distance)),
      options_(options),
      deadline_(deadline),
      search_(grid),
      finder_(grid) {}

CbsOutcome CbsSearch::run() {
  CbsOutcome outcome;
  tree_.assign(1, TreeNode());
  if (planRoot(outcome)) {
    open_.emplace(tree_[0].cost, tree_[0].conflicts, 0);
    outcome.status = CbsOutcome::Status::kTreeExhausted;
    bool ended = false;
    while (!open_.empty() && !ended) {
      const int id = std::get<2>(open_.top());
      open_.pop();
      ended = !expand(id, outcome);
    }
    // A branch closed by a search's budget might have held a solution: not a proof of none.
    if (!ended && budget_hit_) outcome.status = CbsOutcome::Status::kLowLevelLimit;
  }
  outcome.ct_nodes = static_cast<long>(tree_.size());
  outcome.expansions = expansions_;
  outcome.low_level_calls = low_level_calls_;
  outcome.bypasses = bypasses_;
  return outcome;
}

bool CbsSearch::planRoot(CbsOutcome& outcome) {
  TreeNode& root = tree_[0];
  root.paths.resize(starts_.size());
  for (int a = 0; a < static_cast<int>(starts_.size()); ++a) {
    if (deadline_.expired()) {
      outcome.status = CbsOutcome::Status::kTimeLimit;
      return false;
    }
    const SpaceTimePlan plan = replan(a, AgentConstraints(), root.paths);
    if (!plan.found) {
      outcome.status =
          budget_hit_ ? CbsOutcome::Status::kRootSearchLimit : CbsOutcome::Status::kUnreachable;
      outcome.agent = a;
      return false;
    }
    root.paths[a] = std::make_shared<const IdPath>(plan.cells);
    root.cost += pathCost(plan.cells);
  }
  root.conflicts = finder_.find(root.paths);
  return true;
}

bool CbsSearch::expand(int id, CbsOutcome& outcome) {
  std::vector<Conflict> conflicts;
  if (finder_.find(tree_[id].paths, &conflicts) == 0) {
    outcome.status = CbsOutcome::Status::kSolved;
    for (const auto& p : tree_[id].paths) outcome.paths.push_back(*p);
    return false;
  }
  if (deadline_.expired()) {
    outcome.status = CbsOutcome::Status::kTimeLimit;
    return false;
  }
  if (static_cast<long>(tree_.size()) + 2 > options_.max_nodes) {
    outcome.status = CbsOutcome::Status::kNodeLimit;
    return false;
  }
  const Conflict conflict = choose(id, conflicts);
  std::vector<TreeNode> children;
  for (int side = 0; side < 2; ++side) {
    TreeNode node;
    if (!child(id, conflict, side, node)) continue;  // no solution this way (or out of budget)
    if (options_.bypass && node.cost == tree_[id].cost && node.conflicts < tree_[id].conflicts) {
      // Bypass: the parent's constraints admit this path too; take it and look again.
      tree_[id].paths = std::move(node.paths);
      tree_[id].conflicts = node.conflicts;
      open_.emplace(tree_[id].cost, tree_[id].conflicts, id);
      ++bypasses_;
      return true;
    }
    children.push_back(std::move(node));
  }
  for (auto& node : children) {
    open_.emplace(node.cost, node.conflicts, static_cast<int>(tree_.size()));
    tree_.push_back(std::move(node));
  }
  return true;
}

bool CbsSearch::child(int id, const Conflict& conflict, int side, TreeNode& node) {
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
  const SpaceTimePlan plan = replan(added.agent, constraints, tree_[id].paths);
  if (!plan.found) return false;
  node.parent = id;
  node.constraint = added;
  node.paths = tree_[id].paths;
  node.cost = tree_[id].cost - pathCost(*node.paths[added.agent]) + pathCost(plan.cells);
  node.paths[added.agent] = std::make_shared<const IdPath>(plan.cells);
  node.conflicts = finder_.find(node.paths);
  return true;
}

AgentConstraints CbsSearch::constraintsOf(int id, int agent) const {
  AgentConstraints constraints;
  for (int k = id; k > 0; k = tree_[k].parent)
    if (tree_[k].constraint.agent == agent) constraints.add(tree_[k].constraint);
  return constraints;
}

SpaceTimePlan CbsSearch::replan(int agent, const AgentConstraints& constraints,
                                const std::vector<cbs::SharedPath>& paths) {
  const cbs::ConflictAvoidanceTable avoid(grid_, paths, agent);
  SpaceTimeRequest request;
  request.start = starts_[agent];
  request.goal = goals_[agent];
  request.constraints = &constraints;
  request.conflict_counter = &avoid;
  request.heuristic = distance_[agent].get();
  request.max_expansions = options_.max_expansions;
  request.deadline = &deadline_;
  const SpaceTimePlan plan = search_.plan(request);
  expansions_ += plan.expansions;
  ++low_level_calls_;
  budget_hit_ = budget_hit_ || plan.out_of_budget;
  return plan;
}

// Cardinal conflicts first (Boyarski et al., "ICBS: Improved Conflict-Based Search", IJCAI
// 2015): a conflict is cardinal for an agent when all its optimal paths under its constraints
// pass through it (MDD width 1 there, or the agent is already parked on the cell), so splitting
// on it raises the cost of both children and the lower bound grows fastest.
Conflict CbsSearch::choose(int id, const std::vector<Conflict>& list) {
  std::map<int, std::vector<int>> single;  // agent -> its MDD's width-1 cells by time
  const auto cardinalFor = [&](int agent, const Conflict& c, bool first_side) {
    const IdPath& path = *tree_[id].paths[agent];
    const int cost = static_cast<int>(path.size()) - 1;
    if (!c.move && c.t >= cost) return true;  // parked on its goal: must arrive later
    auto it = single.find(agent);
    if (it == single.end())
      it = single
               .emplace(agent, mddSingletons(grid_, path.front(), path.back(), cost,
                                             constraintsOf(id, agent), *distance_[agent]))
               .first;
    const std::vector<int>& at = it->second;
    if (!c.move) return at[c.t] == c.cell;
    const int from = first_side ? c.a_from : c.b_from, to = first_side ? c.a_to : c.b_to;
    return c.t + 1 <= cost && at[c.t] == from && at[c.t + 1] == to;
  };
  int best = 0, best_rank = -1;
  for (std::size_t i = 0; i < list.size() && best_rank < 2; ++i) {
    // Each agent's first look builds its MDD (a search of its time-expanded grid that does not
    // look at the deadline): between conflicts, a stop request or the deadline ends the choice
    // (the search then ends at its next check).
    if (i > 0 && deadline_.expired()) break;
    const int rank = static_cast<int>(cardinalFor(list[i].a, list[i], true)) +
                     static_cast<int>(cardinalFor(list[i].b, list[i], false));
    if (rank > best_rank) best_rank = rank, best = static_cast<int>(i);
  }
  return list[best];
}

}  // namespace cosim
