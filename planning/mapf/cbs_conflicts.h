#pragma once
// Conflicts between the agents' paths for Conflict-Based Search (conflict_based_search.h): finding
// them, and the cells an agent's optimal paths must all visit, which tell a cardinal conflict
// (Boyarski et al., "ICBS: Improved Conflict-Based Search", IJCAI 2015) from the others.
#include <cstddef>
#include <vector>

#include "planning/mapf/cbs_constraints.h"
#include "planning/mapf/goal_distance.h"

namespace cosim::cbs {

struct Conflict {
  int a = -1, b = -1, t = 0;
  bool move = false;
  int cell = 0;                                    // vertex conflict
  int a_from = 0, a_to = 0, b_from = 0, b_to = 0;  // move conflict (between t and t + 1)
};

// Finds the conflicts between the paths (same rules as MapfGrid::moveKey: vertex, swap and
// crossing diagonals; agents stay on their goals).
class ConflictFinder {
 public:
  explicit ConflictFinder(const MapfGrid& grid);

  // All conflicts, in time order, up to `keep` of them in `list` (if given); returns the count.
  int find(const std::vector<SharedPath>& paths, std::vector<Conflict>* list = nullptr,
           std::size_t keep = 64);

 private:
  std::vector<int> cell_owner_, cell_stamp_, move_owner_, move_stamp_;
  const MapfGrid* grid_;
  int stamp_ = 0;
};

// The cells every path of length `cost` from start to goal that respects `constraints` must
// visit: result[t] is the only cell of the MDD's level t (Sharon et al., "The increasing cost
// tree search for optimal multi-agent pathfinding", AIJ 2013), or -1 if the level is wider.
std::vector<int> mddSingletons(const MapfGrid& grid, int start, int goal, int cost,
                               const SpaceTimeConstraints& constraints, GoalDistance& distance);

}  // namespace cosim::cbs
