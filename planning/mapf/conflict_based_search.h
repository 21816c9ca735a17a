#pragma once
// Conflict-Based Search (Sharon, Stern, Felner, Sturtevant, "Conflict-based search for optimal
// multi-agent pathfinding", Artificial Intelligence 219, 2015): the optimal reference. The high
// level searches a tree of constraint sets best-first by sum of costs; at each node the first
// conflict between the agents' paths splits it into two children, each forbidding one of the two
// agents its part of the conflict; the low level (space-time A* with the true-distance heuristic
// of Reverse Resumable A*) replans that agent under its constraints, breaking ties towards fewer
// conflicts with the other agents (conflict avoidance table, §4.3). Bypassing (Boyarski et al.,
// "Don't split, try to work it out: bypassing conflicts in multi-agent pathfinding", ICAPS 2015):
// a child with the parent's cost and fewer conflicts replaces the parent's path instead of
// branching. Both keep the sum of costs optimal.
// The search itself is CbsSearch (cbs_search.h); this planner gives it the instance's grid and
// heuristics and turns its typed outcome into the MapfResult.
#include "planning/mapf/cbs_search.h"
#include "planning/mapf/mapf_planner.h"

namespace cosim {

class ConflictBasedSearch final : public MapfPlanner {
 public:
  explicit ConflictBasedSearch(ConflictBasedSearchOptions options) : options_(options) {}
  std::string name() const override { return "cbs"; }
  MapfResult solve(const MapfQuery& query, const StopToken& stop) override;

 private:
  ConflictBasedSearchOptions options_;
};

}  // namespace cosim
