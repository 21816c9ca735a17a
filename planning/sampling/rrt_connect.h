#pragma once
// RRT-Connect (Kuffner & LaValle 2000, "RRT-Connect: an efficient approach to single-query path
// planning"): one tree from the start and one from the goal; each iteration extends one tree one
// step towards a random sample, then greedily extends the other tree towards the new node until
// it reaches it (the trees meet: a path) or is blocked; then the trees swap roles. It stops at
// the first path; max_nodes bounds the nodes of both trees together.
#include "planning/planner.h"
#include "planning/sampling/sampling_context.h"

namespace cosim {

class RrtConnect : public Planner {
 public:
  explicit RrtConnect(const SamplingOptions& options) : options_(options) {}
  std::string name() const override { return "rrt_connect"; }
  PlanResult solve(const PlanningProblem& problem, const StopToken& stop) override;

 private:
  SamplingOptions options_;
};

}  // namespace cosim
