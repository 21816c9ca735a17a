#pragma once
// RRT* (Karaman & Frazzoli 2011, "Sampling-based algorithms for optimal motion planning") as seed
// 003 runs it (Script 8): RRT plus choose-parent among the nodes within a fixed rewire radius and
// rewiring of those nodes through the new one. Two variants share this loop:
// - RRT*FN, fixed nodes (Adiyatov & Varol 2013; seed 003 Script 9): once the tree holds more
//   than max_tree_nodes nodes, a childless node is removed before each sample; seed 003's policy
//   removes the childless node farthest from the goal.
// - Informed RRT* (Gammell, Srinivasa & Barfoot 2014): once a path of cost c_best exists, samples
//   are drawn from the ellipsoid |x - start| + |x - goal| <= c_best, and new nodes that cannot
//   improve the path (cost-to-come + distance to goal >= c_best) are not added. The tree is not
//   pruned (Gammell's optional pruning step is left out).
#include "planning/planner.h"
#include "planning/sampling/sampling_context.h"

namespace cosim {

struct RrtStarOptions {
  SamplingOptions common;
  // Seed 003's "maximum allowed distance for optimisation"; 0 = k-nearest RRT* instead
  // (k = e (1 + 1/d) log n, Karaman & Frazzoli 2011), which stays cheap as the tree densifies.
  double rewire_radius = 4.0;
  int max_tree_nodes = 0;  // RRT*FN cap M; 0 = no cap (plain RRT*)
  bool informed = false;   // Informed RRT*
};

class RrtStar : public Planner {
 public:
  explicit RrtStar(const RrtStarOptions& options) : options_(options) {}
  std::string name() const override;
  PlanResult solve(const PlanningProblem& problem) override;

 private:
  RrtStarOptions options_;
};

}  // namespace cosim
