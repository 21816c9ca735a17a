#include "planning/mapf/lacam_search.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "planning/mapf/configuration_table.h"
#include "planning/mapf/constraint_trees.h"
#include "planning/mapf/goal_distance_table.h"
#include "planning/mapf/id_pair_set.h"
#include "planning/mapf/pibt_step.h"
#include "planning/mapf/row_arena.h"
#include "planning/mapf/split_mix64.h"

namespace cosim {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

// A configuration in the high-level search. Its vertices, priorities and agent order live in
// row arenas under the same id.
struct HighLevelNode {
  std::uint32_t parent;      // on the best known way from the start
  std::uint32_t first_edge;  // successors found from here (list in the edge arrays)
  std::int64_t g, h;
};

class LacamSearch {
 public:
  LacamSearch(const MapfGraph& graph, std::span<const int> starts, std::span<const int> goals,
              const LacamOptions& options, const StopToken& deadline, std::uint64_t seed,
              const GoalDistanceTable& distance)
      : graph_(graph),
        starts_(starts),
        goals_(goals),
        n_(static_cast<int>(starts.size())),
        options_(options),
        deadline_(deadline),
        distance_(distance),
        rng_(seed),
        pibt_(graph, distance, goals, options.swap),
        table_(starts.size()),
        priorities_(starts.size()),
        orders_(starts.size()),
        next_(starts.size()) {}

  LacamOutcome run();

 private:
  // The outcome once the loop has ended: solved, or why not (the open list ran empty, the memory
  // cap, else the deadline); for a solution, what ended its anytime phase.
  LacamOutcome conclude(bool out_of_memory, bool budget_spent);
  std::uint32_t createNode(std::span<const int> c, std::uint64_t hash, std::uint32_t parent,
                           std::int64_t g);
  void expandConstraint(std::uint32_t node, std::uint32_t constraint);
  std::int64_t edgeCost(std::span<const int> from, std::span<const int> to) const;
  std::int64_t heuristic(std::span<const int> c) const;
  // Adds the edge unless it is known; returns whether it was new.
  bool addEdge(std::uint32_t from, std::uint32_t to, std::int64_t cost);
  // A shorter way to `to` (via `from`), propagated to everything behind it.
  void rewire(std::uint32_t from, std::uint32_t to, std::int64_t cost);
  bool isGoal(std::span<const int> c) const {
    return std::equal(c.begin(), c.end(), goals_.begin());
  }
  std::int64_t f(std::uint32_t id) const { return nodes_[id].g + nodes_[id].h; }
  bool worthSearching(std::uint32_t id) const { return goal_ == kNone || f(id) < nodes_[goal_].g; }
  std::size_t memoryBytes() const;
  // The goal's current way back to the start, kept if its sum of costs is not above the best
  // kept so far (a tie keeps the newer one: its sum of loss is lower).
  void keepIfBetter();
  long sumOfArrivalTimes() const;

  const MapfGraph& graph_;
  std::span<const int> starts_, goals_;
  int n_;
  LacamOptions options_;
  const StopToken& deadline_;
  const GoalDistanceTable& distance_;
  SplitMix64 rng_;
  PibtStep pibt_;

  ConfigurationTable table_;
  RowArena<float> priorities_;
  RowArena<int> orders_;
  std::vector<HighLevelNode> nodes_;
  // Edges between configurations (successor lists), for rewiring.
  std::vector<std::uint32_t> edge_to_, edge_next_;
  std::vector<std::int64_t> edge_cost_;
  IdPairSet edge_set_;
  ConstraintTrees constraints_;  // the low level

  std::vector<std::uint32_t> open_;  // the depth-first stack
  std::uint32_t goal_ = kNone;
  std::vector<int> next_;
  std::vector<FixedMove> fixed_;
  std::vector<std::uint32_t> rewire_queue_;
  std::vector<std::vector<int>> best_;  // the solution to return (keepIfBetter)
  long best_sum_of_costs_ = 0;
  std::vector<int> children_;
  LacamOutcome out_;
};

std::uint32_t LacamSearch::createNode(std::span<const int> c, std::uint64_t hash,
                                      std::uint32_t parent, std::int64_t g) {
  const std::uint32_t id = table_.insert(c, hash);
  nodes_.push_back({parent, kNone, g, heuristic(c)});
  float* p = priorities_.row(priorities_.append());
  if (parent == kNone) {
    // Kei18/lacam2: initial priority d_i(start) / N, so agents far from their goals go first.
    for (int i = 0; i < n_; ++i)
      p[i] = static_cast<float>(distance_(i, c[i])) / static_cast<float>(n_);
  } else {
    // PIBT's dynamic priority (AIJ 2022 §3): +1 per step not on the goal; on the goal only the
    // fractional part (the initial tie-breaker) is kept.
    const float* q = priorities_.row(parent);
    for (int i = 0; i < n_; ++i) p[i] = c[i] != goals_[i] ? q[i] + 1.0f : q[i] - std::floor(q[i]);
  }
  int* order = orders_.row(orders_.append());
  std::iota(order, order + n_, 0);
  // Highest priority first; equal priorities by agent index, so the order is fully determined.
  std::sort(order, order + n_,
            [p](int a, int b) { return p[a] > p[b] || (p[a] == p[b] && a < b); });
  constraints_.addConfiguration();  // the empty constraint: plain PIBT first
  return id;
}

void LacamSearch::expandConstraint(std::uint32_t node, std::uint32_t constraint) {
  const int depth = constraints_.depth(constraint);
  if (depth >= n_) return;
  const int agent = orders_.row(node)[depth];
  const int v = table_[node][agent];
  children_.assign(graph_.neighbours(v).begin(), graph_.neighbours(v).end());
  children_.push_back(v);
  // Random order of the children (Kei18/lacam2 shuffles them too), Fisher-Yates.
  for (std::size_t k = children_.size(); k > 1; --k)
    std::swap(children_[k - 1], children_[rng_.below(static_cast<std::uint32_t>(k))]);
  constraints_.expand(node, constraint, agent, children_);
}

std::int64_t LacamSearch::edgeCost(std::span<const int> from, std::span<const int> to) const {
  // Sum of loss: every agent pays 1 unless it is on its goal before and after the step.
  std::int64_t cost = 0;
  for (int i = 0; i < n_; ++i) cost += (from[i] != goals_[i] || to[i] != goals_[i]) ? 1 : 0;
  return cost;
}

std::int64_t LacamSearch::heuristic(std::span<const int> c) const {
  std::int64_t h = 0;
  for (int i = 0; i < n_; ++i) h += distance_(i, c[i]);
  return h;
}

bool LacamSearch::addEdge(std::uint32_t from, std::uint32_t to, std::int64_t cost) {
  if (!edge_set_.insert(from, to)) return false;
  edge_to_.push_back(to);
  edge_cost_.push_back(cost);
  edge_next_.push_back(nodes_[from].first_edge);
  nodes_[from].first_edge = static_cast<std::uint32_t>(edge_to_.size() - 1);
  return true;
}

void LacamSearch::rewire(std::uint32_t from, std::uint32_t to, std::int64_t cost) {
  // IJCAI 2023 Alg. 2 (lines 24-30): propagate a lower g through the known edges. Every edge
  // already satisfies g(b) <= g(a) + c(a, b) (the propagation below restores it whenever a g
  // drops), so only the new edge can improve anything: start from it rather than from all of
  // `from`'s successors, as the reference code does, which costs a scan per rediscovery. A
  // queue is enough: a label-correcting Dijkstra on positive costs.
  bool goal_improved = false;
  const auto lower = [this, &goal_improved](std::uint32_t a, std::uint32_t b, std::int64_t g) {
    if (g >= nodes_[b].g) return;
    nodes_[b].g = g;
    nodes_[b].parent = a;
    rewire_queue_.push_back(b);
    if (b == goal_) {
      ++out_.improvements;
      out_.last_improvement_ms = deadline_.elapsedMs();
      goal_improved = true;
    }
    if (worthSearching(b)) open_.push_back(b);
  };
  rewire_queue_.clear();
  lower(from, to, nodes_[from].g + cost);
  for (std::size_t k = 0; k < rewire_queue_.size(); ++k) {
    const std::uint32_t a = rewire_queue_[k];
    for (std::uint32_t e = nodes_[a].first_edge; e != kNone; e = edge_next_[e])
      lower(a, edge_to_[e], nodes_[a].g + edge_cost_[e]);
  }
  if (goal_improved) keepIfBetter();
}

std::size_t LacamSearch::memoryBytes() const {
  return table_.bytes() + priorities_.bytes() + orders_.bytes() +
         nodes_.capacity() * sizeof(HighLevelNode) +
         edge_to_.capacity() * (2 * sizeof(std::uint32_t) + sizeof(std::int64_t)) +
         constraints_.bytes() + open_.capacity() * sizeof(std::uint32_t) + edge_set_.bytes();
}

void LacamSearch::keepIfBetter() {
  const long soc = sumOfArrivalTimes();
  if (!best_.empty() && soc > best_sum_of_costs_) return;
  best_sum_of_costs_ = soc;
  best_.clear();
  for (std::uint32_t id = goal_; id != kNone; id = nodes_[id].parent) {
    const auto c = table_[id];
    best_.emplace_back(c.begin(), c.end());
  }
  std::reverse(best_.begin(), best_.end());
}

long LacamSearch::sumOfArrivalTimes() const {
  // Walking back from the goal, an agent's arrival is one step after the last configuration
  // that has it off its goal.
  long depth = -1;
  for (std::uint32_t id = goal_; id != kNone; id = nodes_[id].parent) ++depth;
  std::vector<long> arrival(n_, -1);
  long t = depth, total = 0;
  int open = n_;
  for (std::uint32_t id = goal_; id != kNone && open > 0; id = nodes_[id].parent, --t) {
    const auto c = table_[id];
    for (int i = 0; i < n_; ++i)
      if (arrival[i] < 0 && c[i] != goals_[i]) arrival[i] = t + 1, total += t + 1, --open;
  }
  return total;
}

LacamOutcome LacamSearch::run() {
  const std::uint32_t root = createNode(starts_, ConfigurationTable::hash(starts_), kNone, 0);
  open_.push_back(root);
  const long refine_budget = options_.refine_iterations > 0
                                 ? options_.refine_iterations
                                 : std::max<long>(1, 5'000'000 / std::max(1, n_));
  long solved_at = 0;  // iteration of the first solution
  bool out_of_memory = false, budget_spent = false;
  while (!open_.empty()) {
    if (deadline_.expired()) break;
    // Checked every 64 iterations: capacity() sums are cheap but not free.
    if ((out_.iterations & 63) == 0 && memoryBytes() > options_.max_memory_bytes) {
      out_of_memory = true;
      break;
    }
    if (goal_ != kNone && out_.iterations - solved_at >= refine_budget) {
      budget_spent = true;
      break;
    }
    ++out_.iterations;
    const std::uint32_t top = open_.back();
    if (constraints_.exhausted(top) || !worthSearching(top)) {
      open_.pop_back();  // every constraint tried, or it cannot lead to a better solution
      continue;
    }
    if (goal_ == kNone && isGoal(table_[top])) {
      goal_ = top;
      out_.first_solution_ms = deadline_.elapsedMs();
      out_.first_sum_of_loss = nodes_[top].g;
      keepIfBetter();
      out_.first_sum_of_costs = best_sum_of_costs_;
      solved_at = out_.iterations;
      if (!options_.anytime) break;
      continue;  // LaCAM*: keep searching; the goal node itself is discarded next (f = g)
    }
    const std::uint32_t constraint = constraints_.take(top);
    expandConstraint(top, constraint);
    constraints_.fixedMoves(constraint, fixed_);
    const std::span<const int> from = table_[top];
    if (!pibt_.next(from, {orders_.row(top), static_cast<std::size_t>(n_)}, fixed_, rng_, next_)) {
      ++out_.generator_failures;
      continue;
    }
    const std::uint64_t hash = ConfigurationTable::hash(next_);
    const std::uint32_t known = table_.find(next_, hash);
    const std::int64_t cost = edgeCost(from, next_);
    if (known != ConfigurationTable::kAbsent) {
      ++out_.rediscoveries;
      if (addEdge(top, known, cost)) rewire(top, known, cost);
      // Re-insert the known configuration, or (rarely) restart from the start.
      std::uint32_t again = known;
      if (rng_.unit() < options_.restart_rate) again = root, ++out_.restarts;
      if (worthSearching(again)) open_.push_back(again);
      continue;
    }
    const std::uint32_t child = createNode(next_, hash, top, nodes_[top].g + cost);
    addEdge(top, child, cost);
    if (worthSearching(child)) open_.push_back(child);
  }
  return conclude(out_of_memory, budget_spent);
}

LacamOutcome LacamSearch::conclude(bool out_of_memory, bool budget_spent) {
  out_.nodes = static_cast<long>(nodes_.size());
  out_.memory_bytes = memoryBytes();
  if (goal_ != kNone) {
    out_.status = LacamOutcome::Status::kSolved;
    out_.final_sum_of_loss = nodes_[goal_].g;
    out_.proven_optimal = open_.empty();
    using End = LacamOutcome::AnytimeEnd;
    out_.anytime_end = !options_.anytime ? End::kNone
                       : open_.empty()   ? End::kOptimal
                       : budget_spent    ? End::kIterations
                       : out_of_memory   ? End::kMemoryLimit
                                         : End::kTimeLimit;
    out_.configurations = std::move(best_);
  } else if (open_.empty()) {
    out_.status = LacamOutcome::Status::kNoSolution;
    out_.message = "no solution exists (the search space is exhausted)";
  } else if (out_of_memory) {
    out_.status = LacamOutcome::Status::kMemoryLimit;
    out_.message = "memory limit reached (" + std::to_string(options_.max_memory_bytes >> 20) +
                   " MB) after " + std::to_string(out_.nodes) + " configurations";
  } else {
    out_.status = LacamOutcome::Status::kTimeLimit;
    out_.message = deadline_.stopRequested() ? "stopped" : "time limit reached";
  }
  return std::move(out_);
}

}  // namespace

LacamOutcome searchLacam(const MapfGraph& graph, std::span<const int> starts,
                         std::span<const int> goals, const LacamOptions& options,
                         const StopToken& deadline, std::uint64_t seed) {
  const GoalDistanceTable distance(graph, goals);
  const std::string unreachable = checkGoalsReachable(distance, starts, deadline);
  if (!unreachable.empty()) {
    LacamOutcome out;
    out.status =
        deadline.expired() ? LacamOutcome::Status::kTimeLimit : LacamOutcome::Status::kUnreachable;
    out.message = unreachable;
    out.distance_table_bytes = distance.bytesReached();
    return out;
  }
  LacamSearch search(graph, starts, goals, options, deadline, seed, distance);
  LacamOutcome out = search.run();
  out.distance_table_bytes = distance.bytesReached();
  return out;
}

}  // namespace cosim
