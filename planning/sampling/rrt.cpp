#include "planning/sampling/rrt.h"

#include <algorithm>

#include "planning/sampling/sampling_tree.h"

namespace cosim {

PlanResult Rrt::solve(const PlanningProblem& problem, const StopToken& stop) {
  SamplingContext ctx(problem, stop);
  if (!ctx.invalid().empty()) return ctx.reject();
  const SamplingOptions& o = options_;
  SamplingTree tree(initialCapacity(o), o.linear_scan);
  std::uint32_t goal_node = SamplingTree::kNone;
  // A node within goal_tolerance of the goal tries the straight edge to it.
  auto tryGoal = [&](std::uint32_t id) {
    const Eigen::Vector3d& p = tree.position(id);
    if (p == ctx.goal()) {
      goal_node = id;
      return;
    }
    const double d = (ctx.goal() - p).norm();
    if (d <= o.goal_tolerance && ctx.segmentFree(p, ctx.goal()))
      goal_node = tree.add(ctx.goal(), id, tree.cost(id) + d);
  };
  tryGoal(tree.add(ctx.start(), SamplingTree::kNone, 0.0));

  double iterations = 0;
  while (!ctx.shouldStop(o, tree.generated(), goal_node != SamplingTree::kNone)) {
    ++iterations;
    const Eigen::Vector3d target = ctx.sample(goal_node == SamplingTree::kNone ? o.goal_bias : 0.0);
    const std::uint32_t nearest = tree.index().nearest(target);
    const Eigen::Vector3d& from = tree.position(nearest);
    const Eigen::Vector3d x_new = SamplingContext::steer(from, target, o.step);
    if (x_new == from || !ctx.segmentFree(from, x_new)) continue;
    const std::uint32_t id = tree.add(x_new, nearest, tree.cost(nearest) + (x_new - from).norm());
    if (goal_node == SamplingTree::kNone) tryGoal(id);
  }

  PlanResult result;
  if (goal_node != SamplingTree::kNone) result.path = tree.pathTo(goal_node);
  result.counters["iterations"] = iterations;
  result.counters["nodes"] = static_cast<double>(tree.generated());
  return ctx.finish(std::move(result), o);
}

}  // namespace cosim
