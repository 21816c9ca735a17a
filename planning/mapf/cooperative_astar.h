#pragma once
// Cooperative A* and Hierarchical Cooperative A* (Silver 2005, "Cooperative Pathfinding", §3-4;
// seed 004 §3.3-3.4): agents are planned one after another in space-time; each plan goes into
// the reservation table and is a moving obstacle for the agents planned after it; an agent that
// has arrived occupies its goal for ever. CA* guides each search with the Manhattan (Chebyshev
// on 8-connected grids) distance, HCA* with the true distance of Reverse Resumable A*.
#include "planning/mapf/mapf_planner.h"
#include "planning/mapf/priority_policy.h"

namespace cosim {

struct CooperativeAStarOptions {
  bool abstract_heuristic = false;  // false: CA*; true: HCA* (RRA* heuristic)
  PriorityPolicy priorities = PriorityPolicy::kFixed;
  long max_expansions = 2'000'000;  // per single-agent search
};

class CooperativeAStar final : public MapfPlanner {
 public:
  explicit CooperativeAStar(CooperativeAStarOptions options) : options_(options) {}
  std::string name() const override { return options_.abstract_heuristic ? "hca_star" : "ca_star"; }
  MapfResult solve(const MapfQuery& query, const StopToken& stop) override;

 private:
  CooperativeAStarOptions options_;
};

}  // namespace cosim
