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
// thousand tables then fit twice as well in the caches). Agents with the same goal share one
// row (a distance to a goal does not depend on who walks it). The memory comes zeroed from the
// system (calloc: fresh pages of a large block are mapped on first write), so untouched parts
// of the tables cost nothing; bytesReached() counts what the searches have written.
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
    const std::size_t i = static_cast<std::size_t>(row_of_agent_[agent]) * vertices_ + v;
    const std::uint32_t e = narrow_ ? narrow_entries_[i] : wide_entries_[i];
    return e != 0 ? e - 1 : search(agent, v);
  }
  // Bytes reserved (address space: a row per distinct goal) and written so far (entries
  // reached, frontiers): the second is what the tables really occupy, give or take a page per
  // row.
  std::size_t bytes() const;
  std::size_t bytesReached() const;
  int rowCount() const { return static_cast<int>(frontiers_.size()); }
  int rowOf(int agent) const { return row_of_agent_[agent]; }

 private:
  struct Free {
    void operator()(void* p) const { std::free(p); }
  };
  // Continues the agent's search until v is reached (its distance) or nothing is left
  // (kUnreachable).
  std::uint32_t search(int agent, int v) const;
  template <typename Entry>
  std::uint32_t searchIn(Entry* entries, int row, int v) const;

  const MapfGraph& graph_;
  std::size_t vertices_;
  bool narrow_;
  std::unique_ptr<std::uint16_t[], Free> narrow_entries_;  // agent-major
  std::unique_ptr<std::uint32_t[], Free> wide_entries_;
  std::vector<int> row_of_agent_;  // agents with one goal share its row
  // Each row's search frontier, a ring buffer (capacity a power of two), and how many entries
  // of the row the search has set.
  struct Frontier {
    std::vector<int> ring;
    std::size_t head = 0, size = 0;
    std::size_t reached = 0;
  };
  mutable std::vector<Frontier> frontiers_;
};

// Looks up every agent's start (which runs most of the searches, on all cores): "" when all
// goals can be reached, else why not ("goal of agent 3 is unreachable", or "time limit reached"
// / "stopped" when the deadline ends it first).
// True when every distance on `graph` (+ 1) fits 16 bits: fewer than 65535 vertices, or a
// diameter bound (twice one vertex's eccentricity per connected part) below that.
bool distancesFitSixteenBits(const MapfGraph& graph);

std::string checkGoalsReachable(const GoalDistanceTable& distance, std::span<const int> starts,
                                const StopToken& deadline);

}  // namespace cosim
