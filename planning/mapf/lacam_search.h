#pragma once
// LaCAM* on a MapfGraph: K. Okumura, "LaCAM: Search-Based Algorithm for Quick Multi-Agent
// Pathfinding", AAAI 2023 (Alg. 1), made anytime and eventually optimal in "Improving LaCAM for
// Scalable Eventually Optimal Multi-Agent Pathfinding", IJCAI 2023 (Alg. 2).
//
// The high level searches configurations (one vertex per agent) depth first. Each configuration
// owns a lazily grown tree of constraints (the low level: "agent i goes to vertex v", one agent
// deeper per level, agents in priority order); taking the next constraint node of the top
// configuration, PIBT (pibt_step.h) generates a successor obeying those constraints. A
// configuration already seen is not searched again, but the edge to it is kept; since every
// configuration keeps every constraint node until all are used, the search is complete: it finds
// a solution if one exists, and reports that none exists otherwise.
//
// LaCAM*: after the first solution the search goes on. g is the cost of the best known way to a
// configuration; a shorter way found to a known one is propagated through the kept edges to
// everything behind it (the "rewiring" of the search tree), so the goal's cost can drop; nodes
// whose f = g + h is not below the goal's cost are discarded. When nothing is left the solution
// is optimal. The cost is the sum of loss: an agent pays one per step unless it stays on its goal
// (IJCAI 2023 §2; it equals the sum of costs unless an agent leaves its goal again), with
// h = sum of distances to the goals (admissible).
//
// Constants from the reference implementation (Kei18/lacam2, planner.cpp): the random restart
// rate 0.001 (a rediscovered configuration sends the search back to the start with this
// probability instead of re-inserting it), initial priorities d_i(start) / N, then PIBT's
// dynamic priorities (+1 per step away from the goal, back to the fractional part on it).
#include <atomic>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/stop_token.h"
#include "planning/mapf/mapf_graph.h"

namespace cosim {

struct LacamOptions {
  bool anytime = true;  // false: stop at the first solution (LaCAM rather than LaCAM*)
  // Iterations the anytime phase may take after the first solution; 0: 5e6 / N. An iteration
  // costs about the same per agent, so the default is about the same work (near a second here)
  // for any team, and unlike a time budget it gives the same result on every run. The phase
  // also ends at the time limit (then the result depends on the machine's speed), the memory
  // cap, or when the solution is proven optimal.
  long refine_iterations = 0;
  bool swap = true;             // PIBT's swap technique (IJCAI 2023 §4)
  double restart_rate = 0.001;  // Kei18/lacam2 default (-r)
  // The search's own memory (configurations, priorities, orders, edges, constraint nodes, hash
  // table). At the cap the anytime phase ends with the best solution so far; before a solution
  // the search fails ("memory limit").
  std::size_t max_memory_bytes = std::size_t(1) << 30;
};

struct LacamOutcome {
  enum class Status { kSolved, kNoSolution, kUnreachable, kTimeLimit, kMemoryLimit };
  Status status = Status::kTimeLimit;
  std::string message;  // why it failed, empty when solved
  // Solved: start, ..., goals (a vertex per agent). The search minimises the sum of loss; of the
  // solutions it finds (the first and each improvement) this is the one with the lowest sum of
  // costs, the cost cosim reports, so the reported cost never rises on the way (the two can move
  // apart when an agent leaves its goal again).
  std::vector<std::vector<int>> configurations;
  bool proven_optimal = false;  // the search space was exhausted (sum of loss)
  // How the anytime phase ended (kNone: not run, anytime off).
  enum class AnytimeEnd { kNone, kOptimal, kIterations, kTimeLimit, kMemoryLimit };
  AnytimeEnd anytime_end = AnytimeEnd::kNone;
  long first_sum_of_loss = 0, final_sum_of_loss = 0;  // final: the lowest the search reached
  long first_sum_of_costs = 0;  // of the first solution: arrival times (the cost cosim reports)
  double first_solution_ms = 0.0, last_improvement_ms = 0.0;
  long improvements = 0;  // times the goal's cost dropped after the first solution
  long iterations = 0, nodes = 0, restarts = 0, generator_failures = 0, rediscoveries = 0;
  std::size_t memory_bytes = 0;  // the search's own, at the end
  std::size_t distance_table_bytes = 0;  // written by the lazy searches (bytesReached)
};

LacamOutcome searchLacam(const MapfGraph& graph, std::span<const int> starts,
                         std::span<const int> goals, const LacamOptions& options,
                         const StopToken& deadline, std::uint64_t seed);

}  // namespace cosim
