#pragma once
// The interface of every multi-agent planner (names: independent_astar, lra_star,
// ca_star, hca_star, whca_star, cbs, potential_field, lacam, pibt). A planner sees only the
// instance, a time limit (with an optional stop flag) and a seed; its result is checked by the
// independent SolutionValidator.
#include <string>

#include "planning/mapf/mapf_problem.h"

namespace cosim {

class MapfPlanner {
 public:
  virtual ~MapfPlanner() = default;
  virtual std::string name() const = 0;
  virtual MapfResult solve(const MapfQuery& query) = 0;
};

}  // namespace cosim
