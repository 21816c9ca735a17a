#pragma once
// Checks a MAPF solution on its own, sharing no code with the planners (it reads only the
// occupancy grid and the cell sequences). Rules (seed 004 §1.2, §3.3.2, §4.2):
// - every path starts at its agent's start and ends at its goal, where the agent then stays
//   (it occupies the goal at every later time);
// - every step waits or moves to an adjacent free cell; 4-connected: no diagonal steps;
//   8-connected: a diagonal step needs both side cells free of obstacles; on 3D grids 6-, 18-
//   and 26-connected steps change one, up to two or up to three coordinates, and a step off one
//   axis needs every other cell of the box it spans free;
// - vertex conflict: two agents in one cell at the same time (a cell holds one robot);
// - swap conflict: two agents exchange cells in one step;
// - crossing-diagonal conflict (8-connected; on 3D grids also across a 2x2x2 cube): two agents
//   move diagonally across the same 2x2 block in one step, so both pass its centre at the half
//   step. Our decision: seed 004 forbids
//   it implicitly, since its robots are bodies filling a cell (it forbids a diagonal past a wall
//   corner for the same reason). Swaps and crossings are exactly the cases where two agents moving
//   at constant speed are at the same point at t + 1/2, which is how they are detected here.
// Following (entering a cell its occupant leaves in the same step) is allowed, as in standard
// MAPF. For physical execution: a diagonal mover passes sqrt(2)/2 cell from the centres of the
// side cells, so robots of radius up to sqrt(2)/4 cell never touch a robot standing beside.
#include <string>
#include <vector>

#include "planning/mapf/mapf_problem.h"

namespace cosim {

struct MapfConflict {
  enum class Kind { kVertex, kSwap, kCrossingDiagonal };
  Kind kind = Kind::kVertex;
  int agent_a = 0, agent_b = 0;
  int t = 0;  // vertex: the time both are at `cell`; swap/crossing: the move from t to t + 1
  Cell cell;  // vertex: the shared cell; swap/crossing: agent_a's cell at t
};

struct MapfValidation {
  std::vector<std::string> problems;    // wrong starts/goals, illegal moves, missing paths
  std::vector<MapfConflict> conflicts;  // collisions between agents
  bool valid() const { return problems.empty() && conflicts.empty(); }
};

MapfValidation validateMapfSolution(const MapfInstance& instance,
                                    const std::vector<MapfPath>& paths);

const char* conflictKindName(MapfConflict::Kind kind);

}  // namespace cosim
