#pragma once
// One step of PIBT (Okumura, Machida, Defago, Tamura, "Priority Inheritance with Backtracking for
// Iterative Multi-agent Path Finding", AIJ 310, 2022, Algorithm 1): from the agents' current
// vertices, the next ones, decided agent by agent in priority order. An agent takes the free
// neighbour (or its own vertex) nearest its goal; if another undecided agent stands there, that
// agent inherits the priority and must move first, and if it cannot (backtracking) the first
// agent tries its next candidate. Ties are broken at random.
//
// With the swap technique of Okumura, "Improving LaCAM for Scalable Eventually Optimal
// Multi-Agent Pathfinding" (IJCAI 2023, §4): when two agents meet head-on in a corridor where one
// must pass the other, plain PIBT pushes them back and forth for ever; the swap test simulates
// the push along the corridor and, if a swap is both required and possible, the agent moves away
// from its goal first and pulls the other into its vertex, so that they can exchange places where
// the corridor widens. The required/possible tests follow the reference implementation
// (Kei18/lacam2, planner.cpp) in what they count; the code is ours.
//
// LaCAM uses this as its configuration generator: some agents' moves are fixed beforehand (its
// low-level constraints) and PIBT places the others around them.
//
// Conflicts: two agents never share a vertex, and no two moves with the same MapfGraph key happen
// in one step (swaps; crossing diagonals). An agent may follow another into the vertex it leaves.
#include <cstdint>
#include <span>
#include <vector>

#include "planning/mapf/goal_distance_table.h"
#include "planning/mapf/mapf_graph.h"
#include "planning/mapf/split_mix64.h"

namespace cosim {

// A move imposed on one agent before PIBT places the others (a LaCAM constraint).
struct FixedMove {
  int agent;
  int vertex;  // the agent's current vertex or one of its neighbours
};

class PibtStep {
 public:
  PibtStep(const MapfGraph& graph, const GoalDistanceTable& distance, std::span<const int> goals,
           bool swap);

  // Writes every agent's next vertex to `to`. `order` lists the agents, highest priority first.
  // Returns false if the fixed moves conflict with each other or an agent finds no vertex (only
  // possible around fixed moves); `to` is then meaningless.
  bool next(std::span<const int> from, std::span<const int> order, std::span<const FixedMove> fixed,
            SplitMix64& rng, std::span<int> to);

 private:
  struct Candidate {
    int vertex;
    std::uint32_t key;  // kStay for the agent's own vertex
    std::uint32_t distance;
    float tie;
  };
  static constexpr std::uint32_t kStay = 0xffffffffu;
  static constexpr int kNone = -1;

  bool placeFixed(const FixedMove& m);
  bool push(int agent, SplitMix64& rng);  // PIBT's recursive funcPIBT
  void sortCandidates(int agent, SplitMix64& rng);
  int swapPartner(int agent) const;
  bool swapRequired(int pusher, int puller, int v_pusher, int v_puller) const;
  bool swapPossible(int v_pusher, int v_puller) const;
  // The neighbours of v that a pushed agent could use: not `exclude`, and not a dead end held
  // by an agent resting on its goal there. Returns their number; `last` is one of them.
  int roomAround(int v, int exclude, int& last) const;
  std::uint32_t keyOf(int from, int to) const;
  void reserveKey(std::uint32_t key, int agent);
  void clear();

  const MapfGraph& graph_;
  const GoalDistanceTable& distance_;
  std::span<const int> goals_;
  bool swap_;
  int stride_;  // candidates per agent: max degree + 1

  std::vector<int> now_, next_;                    // per agent; next_ kNone while undecided
  std::vector<int> occupant_now_, occupant_next_;  // per vertex, kNone when empty
  std::vector<int> key_owner_;                     // per move key
  std::vector<Candidate> candidates_;              // per agent, stride_ each
  std::vector<int> touched_vertices_;
  std::vector<std::uint32_t> touched_keys_;
};

}  // namespace cosim
