#pragma once
// The `lacam` multi-robot planner: LaCAM* (lacam_search.h) with PIBT as its configuration
// generator, on the instance's grid as a graph (2D 4-/8-connected or 3D 6-/18-/26-connected).
// Complete; anytime: the first solution comes fast, then the search improves it until its
// iteration budget (refine_iterations), the time limit, the memory cap or a proof of
// optimality. Counters report the first and the final cost and how the improvement ended.
#include "planning/mapf/lacam_search.h"
#include "planning/mapf/mapf_planner.h"

namespace cosim {

class LacamPlanner final : public MapfPlanner {
 public:
  explicit LacamPlanner(LacamOptions options) : options_(options) {}
  std::string name() const override { return "lacam"; }
  MapfResult solve(const MapfQuery& query, const StopToken& stop) override;

 private:
  LacamOptions options_;
};

}  // namespace cosim
