#pragma once
// A* in space-time (x, y, t) for one agent among others (Silver 2005, "Cooperative Pathfinding";
// seed 004 §3.3): the actions are the grid moves plus waiting, each one step long; what other
// agents occupy comes in as SpaceTimeConstraints. Two modes:
// - to the goal (CA*, HCA*, CBS): the agent must end at its goal at a time T after which the
//   goal is never blocked (it stays there for ever); cost = T - start time. Once nothing
//   changes any more (t >= constraints.staticFrom()) states are merged by cell, so the search
//   is finite and reports "no path" when there is none.
// - windowed (WHCA*, Silver §5): the search ends at start time + window; moving or waiting costs
//   one, waiting at the goal costs nothing, and the remaining cost beyond the window is the
//   heuristic (the abstract distance), so the best node at the window's edge is returned.
#include <cstdint>
#include <vector>

#include "core/stop_token.h"
#include "planning/mapf/goal_distance.h"
#include "planning/mapf/mapf_grid.h"
#include "planning/mapf/space_time_constraints.h"

namespace cosim {

struct SpaceTimeRequest {
  int start = 0, goal = 0;
  int start_time = 0;
  int window = 0;  // 0: plan to the goal; > 0: WHCA* window depth
  const SpaceTimeConstraints* constraints = nullptr;           // required
  const SpaceTimeConflictCounter* conflict_counter = nullptr;  // optional tie-break
  GoalDistance* heuristic = nullptr;                           // required
  long max_expansions = 2'000'000;
  const StopToken* deadline = nullptr;
};

struct SpaceTimePlan {
  bool found = false;
  bool out_of_budget = false;  // stopped by the deadline or max_expansions, not exhausted
  std::vector<int> cells;      // cells[i] = cell at start_time + i
  int cost = 0;
  int conflicts = 0;  // soft conflicts along the path (with a conflict counter)
  long expansions = 0;
};

class SpaceTimeAStar {
 public:
  explicit SpaceTimeAStar(const MapfGrid& grid) : grid_(&grid) {}
  SpaceTimePlan plan(const SpaceTimeRequest& request);

 private:
  const MapfGrid* grid_;
};

}  // namespace cosim
