#pragma once
// Every agent's true distance to its goal (breadth-first search back from the goal; the graph's
// moves are symmetric): the heuristic PIBT sorts its candidates by and LaCAM*'s h. Evaluated
// lazily, as in the reference implementation (Kei18/lacam2, dist_table.cpp, after Silver's
// Reverse Resumable A*): an agent's search runs only as far as the vertices asked about, so a
// thousand agents on a 256 x 256 map explore a fraction of it each (most of the planning time
// went into full searches). Looking up a vertex already reached is one load.
//
// Entries hold distance + 1, 0 for "not reached yet", in 16 bits when every distance fits
// (fewer than 65535 vertices, or a diameter bound below that: all MAPF-benchmark maps; a
// thousand tables then fit twice as well in the caches). The memory comes zeroed from the
// system (calloc), so untouched parts of the tables cost nothing.
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/stop_token.h"
#include "planning/mapf/mapf_graph.h"

namespace cosim {

class GoalDistanceTable {
 public:
  static constexpr std::uint32_t kUnreachable = 0xffffffffu;

  GoalDistanceTable(const MapfGraph& graph, std::span<const int> goals);

  // Logically const: the searches it runs only fill in values that never change.
  std::uint32_t operator()(int agent, int v) const {
    const std::size_t i = static_cast<std::size_t>(agent) * vertices_ + v;
    const std::uint32_t e = narrow_ ? narrow_entries_[i] : wide_entries_[i];
    return e != 0 ? e - 1 : search(agent, v);
  }
  std::size_t bytes() const;

 private:
  struct Free {
    void operator()(void* p) const { std::free(p); }
  };
  // Continues the agent's search until v is reached (its distance) or nothing is left
  // (kUnreachable).
  std::uint32_t search(int agent, int v) const;
  template <typename Entry>
  std::uint32_t searchIn(Entry* row, int agent, int v) const;

  const MapfGraph& graph_;
  std::size_t vertices_;
  bool narrow_;
  std::unique_ptr<std::uint16_t[], Free> narrow_entries_;  // agent-major
  std::unique_ptr<std::uint32_t[], Free> wide_entries_;
  // Each agent's search frontier, a ring buffer (capacity a power of two).
  struct Frontier {
    std::vector<int> ring;
    std::size_t head = 0, size = 0;
  };
  mutable std::vector<Frontier> frontiers_;
};

// Looks up every agent's start (which runs most of the searches, on all cores): "" when all
// goals can be reached, else why not ("goal of agent 3 is unreachable", or "time limit reached"
// / "stopped" when the deadline ends it first).
std::string checkGoalsReachable(const GoalDistanceTable& distance, std::span<const int> starts,
                                const StopToken& deadline);

}  // namespace cosim
