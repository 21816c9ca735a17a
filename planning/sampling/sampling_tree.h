#pragma once
// The search tree of the RRT family: node positions, parents and costs-to-come in preallocated
// arrays, children as intrusive doubly linked lists (so a node changes parent or leaves the tree
// in O(1)), and a k-d tree over the positions for nearest-neighbour queries.
#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <vector>

#include "planning/path.h"
#include "planning/sampling/nearest_neighbor_index.h"

namespace cosim {

class SamplingTree {
 public:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  // capacity: expected number of nodes (arrays grow beyond it if needed); linear_scan: see
  // NearestNeighborIndex.
  explicit SamplingTree(std::size_t capacity, bool linear_scan = false);

  // Adds a node; parent = kNone for the root. Returns its id (ids are never reused).
  std::uint32_t add(const Eigen::Vector3d& p, std::uint32_t parent, double cost);
  // Makes new_parent the parent of node, whose cost-to-come becomes new_cost; the costs of all
  // its descendants change by the same amount.
  // With propagate false only `node`'s cost changes and its descendants keep their old costs
  // (seed 003's untested mode-2 hypothesis: a tree kept as parent and cost arrays without a pass
  // over the subtree).
  void reparent(std::uint32_t node, std::uint32_t new_parent, double new_cost,
                bool propagate = true);
  // Removes a node without children from the tree and from the nearest-neighbour index.
  void removeLeaf(std::uint32_t node);

  const Eigen::Vector3d& position(std::uint32_t id) const { return index_.point(id); }
  std::uint32_t parent(std::uint32_t id) const { return nodes_[id].parent; }
  double cost(std::uint32_t id) const { return nodes_[id].cost; }
  bool isLeaf(std::uint32_t id) const { return nodes_[id].first_child == kNone; }
  bool alive(std::uint32_t id) const { return nodes_[id].alive; }
  // Live nodes, and nodes ever added (the "generated nodes" of seed 003).
  std::size_t size() const { return index_.size(); }
  std::size_t generated() const { return nodes_.size(); }
  const NearestNeighborIndex& index() const { return index_; }

  // The waypoints from the root to node.
  Path pathTo(std::uint32_t node) const;

 private:
  struct Node {
    std::uint32_t parent, first_child, next_sibling, prev_sibling;
    double cost;
    bool alive;
  };
  void link(std::uint32_t node, std::uint32_t parent);
  void unlink(std::uint32_t node);

  std::vector<Node> nodes_;
  NearestNeighborIndex index_;
  std::vector<std::uint32_t> stack_;  // scratch for cost propagation
};

}  // namespace cosim
