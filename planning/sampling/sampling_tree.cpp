#include "planning/sampling/sampling_tree.h"

#include <algorithm>

namespace cosim {

SamplingTree::SamplingTree(std::size_t capacity, bool linear_scan) : index_(capacity, linear_scan) {
  nodes_.reserve(capacity);
}

std::uint32_t SamplingTree::add(const Eigen::Vector3d& p, std::uint32_t parent, double cost) {
  const std::uint32_t id = index_.add(p);
  nodes_.push_back({kNone, kNone, kNone, kNone, cost, true});
  if (parent != kNone) link(id, parent);
  return id;
}

void SamplingTree::link(std::uint32_t node, std::uint32_t parent) {
  Node& n = nodes_[node];
  n.parent = parent;
  n.prev_sibling = kNone;
  n.next_sibling = nodes_[parent].first_child;
  if (n.next_sibling != kNone) nodes_[n.next_sibling].prev_sibling = node;
  nodes_[parent].first_child = node;
}

void SamplingTree::unlink(std::uint32_t node) {
  Node& n = nodes_[node];
  if (n.prev_sibling != kNone)
    nodes_[n.prev_sibling].next_sibling = n.next_sibling;
  else if (n.parent != kNone)
    nodes_[n.parent].first_child = n.next_sibling;
  if (n.next_sibling != kNone) nodes_[n.next_sibling].prev_sibling = n.prev_sibling;
  n.parent = n.next_sibling = n.prev_sibling = kNone;
}

void SamplingTree::reparent(std::uint32_t node, std::uint32_t new_parent, double new_cost,
                            bool propagate) {
  unlink(node);
  link(node, new_parent);
  const double delta = new_cost - nodes_[node].cost;
  nodes_[node].cost = new_cost;
  if (!propagate) return;
  stack_.clear();
  for (std::uint32_t c = nodes_[node].first_child; c != kNone; c = nodes_[c].next_sibling)
    stack_.push_back(c);
  while (!stack_.empty()) {
    const std::uint32_t id = stack_.back();
    stack_.pop_back();
    nodes_[id].cost += delta;
    for (std::uint32_t c = nodes_[id].first_child; c != kNone; c = nodes_[c].next_sibling)
      stack_.push_back(c);
  }
}

void SamplingTree::removeLeaf(std::uint32_t node) {
  unlink(node);
  nodes_[node].alive = false;
  index_.remove(node);
}

Path SamplingTree::pathTo(std::uint32_t node) const {
  Path path;
  for (std::uint32_t id = node; id != kNone; id = nodes_[id].parent)
    path.waypoints.push_back(position(id));
  std::reverse(path.waypoints.begin(), path.waypoints.end());
  return path;
}

}  // namespace cosim
