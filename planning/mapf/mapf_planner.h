#pragma once
// The interface of every multi-agent planner (names: independent_astar, lra_star,
// ca_star, hca_star, whca_star, cbs, potential_field, lacam, pibt). A planner sees only the
// instance, a time limit and a seed, and its caller's StopToken (the caller's own deadline and
// stop request; the planner stops at the query's time limit inside it); its result is checked by
// the independent SolutionValidator.
#include <string>

#include "core/stop_token.h"
#include "planning/mapf/mapf_problem.h"

namespace cosim {

class MapfPlanner {
 public:
  virtual ~MapfPlanner() = default;
  virtual std::string name() const = 0;
  virtual MapfResult solve(const MapfQuery& query, const StopToken& stop) = 0;
};

}  // namespace cosim
