#pragma once
// How much memory a multi-agent planner's per-agent tables will really need on an instance,
// checked before it allocates anything (a refusal is bad input, exit 2, not a crash hours in).
// The measure is the planner's own:
// - lacam, pibt: the goal distance tables (GoalDistanceTable): one row per distinct goal over
//   the free cells only, 2 bytes an entry when the map's distances fit 16 bits, else 4. Rows
//   are filled lazily, so this is the worst case (every row searched to the end); on the
//   MovingAI benchmark's brc202d (43151 free of 254930 cells) 1000 agents need 86 MB.
// - hca_star, whca_star, cbs: a Reverse Resumable A* per agent over every cell of the grid
//   (an int distance and a closed byte: 5 bytes a cell, allocated in full).
// - the others (independent_astar, lra_star, ca_star, potential_field) keep per-cell tables
//   shared by all agents, a few bytes a cell.
#include <cstddef>
#include <string>

#include "planning/mapf/mapf_problem.h"

namespace cosim {

constexpr std::size_t kMaxMapfTableBytes = std::size_t{1} << 30;  // about 1 GB

struct MapfMemoryEstimate {
  double bytes = 0.0;
  std::string breakdown;  // e.g. "1000 goals x 43151 free cells x 2 bytes"
};

MapfMemoryEstimate estimateMapfTableMemory(const MapfInstance& instance,
                                           const std::string& planner);

// Throws InputError (file, "agents") naming the estimate when it exceeds kMaxMapfTableBytes.
void checkMapfTableMemory(const MapfInstance& instance, const std::string& planner,
                          const std::string& file);

}  // namespace cosim
