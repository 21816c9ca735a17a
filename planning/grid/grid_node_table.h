#pragma once
// Per-cell search state (cost so far g, parent, open/closed status) kept in one flat array
// indexed by grid cell index and reused across searches; the three fields of a cell share a
// cache line. A search generation counter replaces clearing: a cell whose stamp predates the
// current search is "unseen", so starting a search costs O(1) instead of O(cells). Cost is
// FixedCost for move-sum searches, double for the any-angle ones.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace cosim {

template <class Cost>
class GridNodeTable {
 public:
  enum class State : std::uint32_t { Unseen = 0, Open = 1, OpenVerified = 2, Closed = 3 };

  // Starts a new search over `cells` cells (grows the array if needed).
  void begin(std::size_t cells) {
    if (nodes_.size() < cells) {
      nodes_.assign(cells, Node{});
      base_ = 0;
    }
    if (base_ > std::numeric_limits<std::uint32_t>::max() - 8) {
      for (Node& n : nodes_) n.stamp = 0;
      base_ = 0;
    }
    base_ += 4;
  }

  // Stamps of this search are base_ + State; anything <= base_ belongs to an earlier search.
  State state(std::uint32_t i) const {
    const std::uint32_t s = nodes_[i].stamp;
    return s <= base_ ? State::Unseen : static_cast<State>(s - base_);
  }
  bool seen(std::uint32_t i) const { return nodes_[i].stamp > base_; }
  bool closed(std::uint32_t i) const { return nodes_[i].stamp == base_ + 3; }
  void setState(std::uint32_t i, State s) {
    nodes_[i].stamp = base_ + static_cast<std::uint32_t>(s);
  }

  // Cost so far of a cell seen in this search (the hot loops test seen() first).
  Cost g(std::uint32_t i) const { return nodes_[i].g; }
  std::uint32_t parent(std::uint32_t i) const { return nodes_[i].parent; }
  void set(std::uint32_t i, Cost g, std::uint32_t parent, State s) {
    nodes_[i] = Node{g, parent, base_ + static_cast<std::uint32_t>(s)};
  }

 private:
  struct Node {
    Cost g = Cost();
    std::uint32_t parent = 0;
    std::uint32_t stamp = 0;
  };
  std::vector<Node> nodes_;
  std::uint32_t base_ = 0;
};

}  // namespace cosim
