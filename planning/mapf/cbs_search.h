#pragma once
// Conflict-Based Search itself (conflict_based_search.h is the planner around it), as LaCAM's
// search is in lacam_search.h: a constraint tree searched best-first by sum of costs, split at
// a cardinal conflict first, with bypassing. It ends with a typed status, from which the planner
// derives its PlannerStatus and message.
#include <functional>
#include <memory>
#include <queue>
#include <tuple>
#include <vector>

#include "core/stop_token.h"
#include "planning/mapf/cbs_conflicts.h"
#include "planning/mapf/space_time_astar.h"

namespace cosim {

struct ConflictBasedSearchOptions {
  long max_nodes = 50'000;          // constraint-tree nodes; bounds memory
  long max_expansions = 1'000'000;  // per low-level search
  bool bypass = true;
};

struct CbsOutcome {
  enum class Status {
    kSolved,
    kTimeLimit,        // the deadline (or a stop request) ended the search
    kUnreachable,      // `agent` has no path to its goal at all (root node)
    kRootSearchLimit,  // `agent`'s first low-level search ran out of its budget (root node)
    kNodeLimit,        // the constraint tree reached max_nodes
    kTreeExhausted,    // every branch was closed: there is no solution
    kLowLevelLimit,    // as kTreeExhausted, but some branch was closed by a search's budget
  };
  Status status = Status::kTreeExhausted;
  int agent = -1;                  // kUnreachable, kRootSearchLimit: the agent
  std::vector<cbs::IdPath> paths;  // kSolved: each agent's cells by time, to its arrival
  long ct_nodes = 0, expansions = 0, low_level_calls = 0, bypasses = 0;
};

class CbsSearch {
 public:
  // `distance[a]`: agent a's heuristic towards goals[a] (true distances keep CBS optimal).
  CbsSearch(const MapfGrid& grid, std::vector<int> starts, std::vector<int> goals,
            std::vector<std::unique_ptr<GoalDistance>> distance,
            const ConflictBasedSearchOptions& options, const StopToken& deadline);
  CbsOutcome run();

 private:
  struct TreeNode {
    int parent = -1;
    cbs::Constraint constraint;  // the one this node added (none at the root)
    std::vector<cbs::SharedPath> paths;
    long cost = 0;
    int conflicts = 0;
  };

  bool planRoot(CbsOutcome& outcome);
  // Node `id`, just taken from the open list: a solution if its paths have no conflict, else
  // split at a conflict (or bypassed). False when the search ends here, with `outcome.status`.
  bool expand(int id, CbsOutcome& outcome);
  // The constraints on `agent` along the branch from the root to node `id`.
  cbs::AgentConstraints constraintsOf(int id, int agent) const;
  SpaceTimePlan replan(int agent, const cbs::AgentConstraints& constraints,
                       const std::vector<cbs::SharedPath>& paths);
  // The conflict to split on: cardinal for both agents if there is one, else for one, else the
  // earliest.
  cbs::Conflict choose(int id, const std::vector<cbs::Conflict>& list);
  // Replans one side of `conflict` under the added constraint; false if it finds no path.
  bool child(int id, const cbs::Conflict& conflict, int side, TreeNode& node);

  const MapfGrid& grid_;
  std::vector<int> starts_, goals_;
  std::vector<std::unique_ptr<GoalDistance>> distance_;
  const ConflictBasedSearchOptions& options_;
  const StopToken& deadline_;
  SpaceTimeAStar search_;
  cbs::ConflictFinder finder_;
  std::vector<TreeNode> tree_;  // the constraint tree; node 0 is the root
  // (sum of costs, conflicts, node): best-first, ties towards fewer conflicts, then older nodes.
  using Entry = std::tuple<long, int, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open_;
  long expansions_ = 0, low_level_calls_ = 0, bypasses_ = 0;
  bool budget_hit_ = false;
};

}  // namespace cosim
