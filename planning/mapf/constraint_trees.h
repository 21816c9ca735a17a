#pragma once
// LaCAM's low level (Okumura, AAAI 2023, §3, Alg. 1 lines 9-17): for every configuration of the
// high-level search, a tree of constraints grown lazily and breadth first. The root constrains
// nothing; a node at depth d fixes the moves of the first d agents in the configuration's
// priority order, one child per possible move of the next agent (its neighbours and staying).
// Each configuration keeps the nodes not yet tried in a first-in-first-out queue; a node is
// turned into a successor once, and expanded when it is taken. All trees share one pool.
#include <cstdint>
#include <span>
#include <vector>

#include "planning/mapf/pibt_step.h"

namespace cosim {

class ConstraintTrees {
 public:
  static constexpr std::uint32_t kNone = 0xffffffffu;

  // A new configuration (ids 0, 1, ... in order): its queue holds the empty constraint.
  void addConfiguration();
  bool exhausted(std::uint32_t configuration) const { return heads_[configuration] == kNone; }
  // Takes the configuration's next constraint node (not exhausted).
  std::uint32_t take(std::uint32_t configuration);
  int depth(std::uint32_t node) const { return depth_[node]; }
  // Queues the children of `node`: `agent` moving to each of `vertices`.
  void expand(std::uint32_t configuration, std::uint32_t node, int agent,
              std::span<const int> vertices);
  // The moves `node` fixes, root first.
  void fixedMoves(std::uint32_t node, std::vector<FixedMove>& moves) const;
  std::size_t bytes() const;

 private:
  std::uint32_t add(std::uint32_t parent, int agent, int vertex, int depth);
  void enqueue(std::uint32_t configuration, std::uint32_t node);

  std::vector<std::uint32_t> heads_, tails_;  // per configuration
  // The pool: each node's parent, next in its configuration's queue, the move and the depth.
  std::vector<std::uint32_t> parent_, next_;
  std::vector<int> agent_, vertex_, depth_;
};

}  // namespace cosim
