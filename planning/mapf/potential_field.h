#pragma once
// The artificial potential field baseline (seed 004 §2.3, §4.6; Khatib 1986), on the grid: in
// every step each agent moves to the neighbouring cell (or stays) with the lowest potential
//   U(c) = attraction * |c - goal| + repulsion * sum over blocked cells and other robots o
//          with d = |c - o| < R = influence_radius of (1/d - 1/R),
// i.e. like charges repel with a force ~ 1/d^2 (seed 004 §2.3), cut off at R (shifted so that U
// stays continuous, as Khatib's obstacle potential). Deviation: the goal attracts with a constant
// force (a conical potential) instead of a 1/d^2 one, which would vanish at range and leave every
// distant robot to the repulsive terms. The seed gives no constants; ours are below.
// Moves go through a StepArbiter (no collisions); an agent that has arrived stays. The method is
// neither complete nor optimal: robots stop in local minima (the seed: "it did not work out,
// because of local minima"); the plan fails when a step changes nothing or after max_steps.
#include "planning/mapf/mapf_planner.h"

namespace cosim {

struct PotentialFieldOptions {
  double attraction = 1.0;
  double repulsion = 1.0;
  double influence_radius = 2.0;  // cells
  int max_steps = 0;              // 0 = the number of map cells
};

class PotentialField final : public MapfPlanner {
 public:
  explicit PotentialField(PotentialFieldOptions options) : options_(options) {}
  std::string name() const override { return "potential_field"; }
  MapfResult solve(const MapfQuery& query, const StopToken& stop) override;

 private:
  PotentialFieldOptions options_;
};

}  // namespace cosim
