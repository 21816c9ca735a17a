#pragma once
// A multi-agent path-finding (MAPF) instance and its solution, as plain values (the style of
// whoenig's libMultiRobotPlanning: an instance in, a checked solution out). Conventions (seed 004
// §1.2-1.4 and Stern et al., "Multi-Agent Pathfinding: Definitions, Variants, and Benchmarks",
// SoCS 2019):
// - time is discrete; in one step an agent waits or moves to an adjacent free cell; every action,
//   including a diagonal move on an 8-connected grid, takes one step (the seed's own simplifying
//   assumption, §3.6);
// - paths[i][t] is agent i's cell at time t, from its start at t = 0 to its arrival; after the
//   last entry the agent stays at its goal for ever (it keeps occupying that cell);
// - an agent's cost is its arrival time (path length - 1); sum of costs and makespan follow.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "planning/grid/occupancy_grid.h"
#include "planning/planner_status.h"

namespace cosim {

struct MapfInstance {
  OccupancyGrid grid;  // blocked cells are static obstacles; 3D grids only for lacam and pibt
  // 2D: 4 or 8 (8: diagonal only when both side cells are free, seed 004 §4.2); 3D: 6, 18 or 26
  // (a move off one axis needs every cell of the box it spans free).
  int connectivity = 4;
  std::vector<Cell> starts, goals;
  int agentCount() const { return static_cast<int>(starts.size()); }
};

struct MapfQuery {
  const MapfInstance* instance = nullptr;
  double time_limit_s = 10.0;
  std::uint64_t seed = 1;
};

using MapfPath = std::vector<Cell>;

struct MapfResult {
  bool success = false;  // status == ExactSolution
  PlannerStatus status = PlannerStatus::Unknown;
  // On success, a solution; on failure, whatever the planner had (possibly empty or conflicting;
  // `cosim mapf` reports its conflicts but never calls it a solution).
  std::vector<MapfPath> paths;
  double time_ms = 0.0;
  std::map<std::string, double> counters;  // expansions, replans, ct_nodes, ...
  std::string message;                     // why it failed, empty on success
};

// Arrival time of one path: the step after which the agent never leaves its last cell.
int arrivalTime(const MapfPath& path);
// Sum over agents of the arrival time.
long sumOfCosts(const std::vector<MapfPath>& paths);
// Largest arrival time.
int makespan(const std::vector<MapfPath>& paths);
// Drops repeated final cells, so that paths[i].size() - 1 is the arrival time.
void trimWaitsAtEnd(MapfPath& path);

// Limits on the size of a MAPF instance, checked before any planner allocates. What the
// planners' per-agent tables need depends on the planner: mapf_memory_estimate.h checks it.
// MovingAI's MAPF maps have at most about a million cells.
constexpr long kMaxMapfCells = 16L << 20;  // 4096 x 4096
constexpr int kMaxMapfAgents = 10000;

// Throws InputError if a start or goal is off the grid or blocked, two agents share a start or a
// goal, the connectivity is not one of the grid's, or the instance exceeds the limits above.
// `file` names the source for the message.
void checkMapfInstance(const MapfInstance& instance, const std::string& file);

}  // namespace cosim
