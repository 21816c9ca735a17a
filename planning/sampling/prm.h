#pragma once
// PRM, the probabilistic roadmap (Kavraki, Svestka, Latombe & Overmars 1996), as seed 003
// describes it (Alg. 6; the seed did not implement it): collision-free random states become
// roadmap nodes, each connected to its k nearest nodes by free straight edges, then the shortest
// roadmap path from start to goal is searched (A* with the straight-line heuristic, which returns
// the same path as the seed's Dijkstra). Start and goal are roadmap nodes from the beginning.
// Mode 1 stops sampling as soon as start and goal are in one connected component (tracked with
// union-find); mode 2 places all max_nodes nodes first.
// Deviation from seed 003: a neighbour farther than `step` is not connected, where the seed would
// steer a new node at distance `step` towards it; such a node is just another sample, and keeping
// edges short keeps the roadmap's edge checks cheap.
#include "planning/planner.h"
#include "planning/sampling/sampling_context.h"

namespace cosim {

struct PrmOptions {
  SamplingOptions common;
  int k = 10;  // neighbours per node (the seed's K; it gives no value)
};

class Prm : public Planner {
 public:
  explicit Prm(const PrmOptions& options) : options_(options) {}
  std::string name() const override { return "prm"; }
  PlanResult solve(const PlanningProblem& problem, const StopToken& stop) override;

 private:
  PrmOptions options_;
};

}  // namespace cosim
