#pragma once
// RRT* (Karaman & Frazzoli 2011, "Sampling-based algorithms for optimal motion planning") with
// seed 003's fixed "maximum allowed distance for optimisation" (Script 8): RRT plus choose-parent
// among the nodes within the rewire radius and rewiring of those nodes through the new one.
// Seed 003's own RRT* chose the parent differently (its Fig. 16: "x_old, the parent of x_last, the
// nearest node to x_new, is joined to x_new"; ChooseParent "returns the nearest neighbour"): the
// new node takes the nearest node's parent when that node lies within the rewire radius (the
// thesis's "maximum allowed distance for optimisation") and the edge is free, else the nearest
// node, and only rewiring looks at the whole radius. ChooseParent::NearestParent is that rule
// (planner rrt_star_thesis); it is greedier and leaves longer paths. Variants that share this loop:
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

enum class ChooseParent {
  NearMin,        // Karaman-Frazzoli: the cheapest free edge among the near nodes
  NearestParent,  // seed 003 Fig. 16: the nearest node's parent if near and visible, else nearest
};

struct RrtStarOptions {
  SamplingOptions common;
  ChooseParent choose_parent = ChooseParent::NearMin;
  // Seed 003's "maximum allowed distance for optimisation"; 0 = k-nearest RRT* instead
  // (k = e (1 + 1/d) log n, Karaman & Frazzoli 2011), which stays cheap as the tree densifies.
  double rewire_radius = 4.0;
  int max_tree_nodes = 0;  // RRT*FN cap M; 0 = no cap (plain RRT*)
  bool informed = false;   // Informed RRT*
  // Seed 003's two untested explanations of its mode 2 barely shortening the path (both true is
  // the usual RRT*): a rewired node's new cost passed on to its descendants, and the goal
  // re-attached to any node that reaches it more cheaply, by the goal test or by rewiring
  // (false: it keeps the node that first reached it).
  bool propagate_rewire_costs = true;
  bool reattach_goal = true;
};

class RrtStar : public Planner {
 public:
  explicit RrtStar(const RrtStarOptions& options) : options_(options) {}
  std::string name() const override;
  PlanResult solve(const PlanningProblem& problem, const StopToken& stop) override;

 private:
  RrtStarOptions options_;
};

}  // namespace cosim
