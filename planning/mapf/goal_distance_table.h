#pragma once
// Every agent's true distance to its goal from every vertex (breadth-first search back from the
// goal; the graph's moves are symmetric): the heuristic PIBT sorts its candidates by and
// LaCAM*'s h. Computed in full up front rather than lazily as in Okumura's code, so that a lookup
// in the hot loop is one load and the table is immutable while the search runs. Distances are
// stored in 16 bits when the graph has fewer than 65535 vertices (every MAPF-benchmark map but
// the largest): a thousand agents' tables then fit twice as well in the caches, which PIBT's
// lookups at every agent's neighbours miss otherwise.
#include <cstdint>
#include <span>
#include <vector>

#include "planning/deadline.h"
#include "planning/mapf/mapf_graph.h"

namespace cosim {

class GoalDistanceTable {
 public:
  static constexpr std::uint32_t kUnreachable = 0xffffffffu;

  // Stops early, leaving complete() false, when the deadline expires.
  GoalDistanceTable(const MapfGraph& graph, std::span<const int> goals, const Deadline& deadline);

  bool complete() const { return complete_; }
  std::uint32_t operator()(int agent, int v) const {
    const std::size_t i = static_cast<std::size_t>(agent) * vertices_ + v;
    if (narrow_)
      return narrow_distances_[i] == kNarrowUnreachable ? kUnreachable : narrow_distances_[i];
    return wide_distances_[i];
  }
  std::size_t bytes() const {
    return narrow_distances_.size() * sizeof(std::uint16_t) +
           wide_distances_.size() * sizeof(std::uint32_t);
  }

 private:
  static constexpr std::uint16_t kNarrowUnreachable = 0xffff;
  template <typename T>
  bool fill(std::vector<T>& distances, const MapfGraph& graph, std::span<const int> goals,
            const Deadline& deadline, T unreachable);

  std::size_t vertices_ = 0;
  bool narrow_ = false;
  std::vector<std::uint16_t> narrow_distances_;  // agent-major
  std::vector<std::uint32_t> wide_distances_;
  bool complete_ = true;
};

}  // namespace cosim
