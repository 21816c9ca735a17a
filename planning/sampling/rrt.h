#pragma once
// RRT, the rapidly-exploring random tree (LaValle 1998, "Rapidly-exploring random trees: a new
// tool for path planning"), as seed 003 (Alg. 7) runs it: sample, find the nearest node, steer at
// most `step` towards the sample, add the new node if the edge is free. Mode 1 stops at the first
// path to the goal, mode 2 generates all max_nodes nodes (the path does not change after that:
// RRT never rewires).
#include "planning/planner.h"
#include "planning/sampling/sampling_context.h"

namespace cosim {

class Rrt : public Planner {
 public:
  explicit Rrt(const SamplingOptions& options) : options_(options) {}
  std::string name() const override { return "rrt"; }
  PlanResult solve(const PlanningProblem& problem, const StopToken& stop) override;

 private:
  SamplingOptions options_;
};

}  // namespace cosim
