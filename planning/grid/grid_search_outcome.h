#pragma once
// What every grid search does before and after its main loop: reject queries it cannot start
// (no grid, endpoints outside or blocked), and turn the node table's parent links into a
// GridPlanResult with its counters.
#include <cstdint>
#include <string>
#include <vector>

#include "core/stop_token.h"
#include "planning/grid/grid_node_table.h"
#include "planning/grid/grid_search_space.h"

namespace cosim {

struct GridSearchCounters {
  double expansions = 0;  // cells taken from OPEN and expanded
  double los_checks = 0;  // line-of-sight tests (any-angle planners)
  double pushes = 0;      // entries pushed onto OPEN
};

// True when the query cannot be searched (no grid, an endpoint outside the grid or blocked);
// `result` then holds the failure and its reason ("start cell (3,4,0) is blocked").
bool gridQueryRejected(const GridQuery& query, GridPlanResult& result);

enum class GridSearchEnd { Found, Exhausted, TimeLimit };

// Builds the result from the cell indices goal ... start (empty unless Found): the cells from
// start to goal and their Euclidean length; otherwise success = false with "no path" or
// "time limit".
GridPlanResult gridSearchResult(const GridSearchSpace& space,
                                const std::vector<std::uint32_t>& goal_to_start, GridSearchEnd end,
                                const GridSearchCounters& counters, const StopToken& clock,
                                bool any_angle);

// The same, following parent links from the goal: on Found, the cells from start to goal along
// parent links and their Euclidean length; otherwise success = false with "no path" or "time
// limit".
template <class Cost>
GridPlanResult gridSearchResult(const GridSearchSpace& space, const GridNodeTable<Cost>& nodes,
                                std::uint32_t start, std::uint32_t goal, GridSearchEnd end,
                                const GridSearchCounters& counters, const StopToken& clock,
                                bool any_angle) {
  std::vector<std::uint32_t> chain;
  if (end == GridSearchEnd::Found)
    for (std::uint32_t i = goal;; i = nodes.parent(i)) {
      chain.push_back(i);
      if (i == start) break;
    }
  return gridSearchResult(space, chain, end, counters, clock, any_angle);
}

// How often (in expansions) the searches poll their deadline: cheap enough to be invisible,
// frequent enough to stop within a millisecond.
constexpr std::uint64_t kDeadlinePollMask = 1023;

}  // namespace cosim
