#include "planning/mapf/constraint_trees.h"

#include <algorithm>

namespace cosim {

void ConstraintTrees::addConfiguration() {
  heads_.push_back(kNone);
  tails_.push_back(kNone);
  enqueue(static_cast<std::uint32_t>(heads_.size() - 1), add(kNone, -1, -1, 0));
}

std::uint32_t ConstraintTrees::add(std::uint32_t parent, int agent, int vertex, int depth) {
  parent_.push_back(parent);
  next_.push_back(kNone);
  agent_.push_back(agent);
  vertex_.push_back(vertex);
  depth_.push_back(depth);
  return static_cast<std::uint32_t>(parent_.size() - 1);
}

void ConstraintTrees::enqueue(std::uint32_t configuration, std::uint32_t node) {
  if (tails_[configuration] == kNone)
    heads_[configuration] = node;
  else
    next_[tails_[configuration]] = node;
  tails_[configuration] = node;
}

std::uint32_t ConstraintTrees::take(std::uint32_t configuration) {
  const std::uint32_t node = heads_[configuration];
  heads_[configuration] = next_[node];
  if (heads_[configuration] == kNone) tails_[configuration] = kNone;
  return node;
}

void ConstraintTrees::expand(std::uint32_t configuration, std::uint32_t node, int agent,
                             std::span<const int> vertices) {
  for (const int v : vertices) enqueue(configuration, add(node, agent, v, depth_[node] + 1));
}

void ConstraintTrees::fixedMoves(std::uint32_t node, std::vector<FixedMove>& moves) const {
  moves.clear();
  for (std::uint32_t c = node; c != kNone && depth_[c] > 0; c = parent_[c])
    moves.push_back({agent_[c], vertex_[c]});
  std::reverse(moves.begin(), moves.end());
}

std::size_t ConstraintTrees::bytes() const {
  return (heads_.capacity() + tails_.capacity()) * sizeof(std::uint32_t) +
         parent_.capacity() * (2 * sizeof(std::uint32_t) + 3 * sizeof(int));
}

}  // namespace cosim
