#pragma once
// The baseline without coordination: every agent takes its own shortest path (A*, seed 004
// Algorithm 4.2.1) as if alone. It succeeds only when those paths happen not to conflict (the
// planner checks them with the SolutionValidator); otherwise it reports the conflicting paths
// as a failure.
#include "planning/mapf/mapf_planner.h"

namespace cosim {

class IndependentAStar final : public MapfPlanner {
 public:
  std::string name() const override { return "independent_astar"; }
  MapfResult solve(const MapfQuery& query, const StopToken& stop) override;
};

}  // namespace cosim
