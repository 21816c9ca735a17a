#include "planning/sampling/rrt_connect.h"

#include <algorithm>

#include "planning/sampling/sampling_tree.h"

namespace cosim {

PlanResult RrtConnect::solve(const PlanningProblem& problem, const StopToken& stop) {
  SamplingContext ctx(problem, stop);
  if (!ctx.invalid().empty()) return ctx.reject();
  const SamplingOptions& o = options_;
  const std::size_t capacity = initialCapacity(o) / 2 + 2;
  SamplingTree from_start(capacity), from_goal(capacity);
  auto generated = [&] { return from_start.generated() + from_goal.generated(); };
  from_start.add(ctx.start(), SamplingTree::kNone, 0.0);
  from_goal.add(ctx.goal(), SamplingTree::kNone, 0.0);

  // One step of `tree` towards `target`: the new node, or kNone if the step is blocked (or
  // `target` is already a node).
  auto extend = [&](SamplingTree& tree, const Eigen::Vector3d& target) {
    const std::uint32_t nearest = tree.index().nearest(target);
    const Eigen::Vector3d& from = tree.position(nearest);
    const Eigen::Vector3d x_new = SamplingContext::steer(from, target, o.step);
    if (x_new == from) return nearest;
    if (!ctx.segmentFree(from, x_new)) return SamplingTree::kNone;
    return tree.add(x_new, nearest, tree.cost(nearest) + (x_new - from).norm());
  };

  SamplingTree* a = &from_start;
  SamplingTree* b = &from_goal;
  double iterations = 0;
  std::uint32_t meet_a = SamplingTree::kNone, meet_b = SamplingTree::kNone;
  // Trivial case: start and goal see each other within one step.
  if ((ctx.goal() - ctx.start()).norm() <= o.step && ctx.segmentFree(ctx.start(), ctx.goal()))
    meet_a = meet_b = 0;
  // A first solution ends the search (RRT-Connect is not anytime): only the time limit or a
  // max_nodes the user set stops it before.
  while (meet_a == SamplingTree::kNone && !ctx.shouldStop(o, generated(), false)) {
    ++iterations;
    const std::uint32_t x_new = extend(*a, ctx.sample(0.0));
    if (x_new != SamplingTree::kNone) {
      // Connect: step b towards the new node of a until it gets there or is blocked.
      const Eigen::Vector3d target = a->position(x_new);
      std::uint32_t reached = SamplingTree::kNone;
      while (!ctx.shouldStop(o, generated(), false)) {
        const std::uint32_t y = extend(*b, target);
        if (y == SamplingTree::kNone) break;
        if (b->position(y) == target) {
          reached = y;
          break;
        }
      }
      if (reached != SamplingTree::kNone) {
        meet_a = x_new;
        meet_b = reached;
        break;
      }
    }
    std::swap(a, b);
  }

  PlanResult result;
  if (meet_a != SamplingTree::kNone) {
    // The two half paths end at the same point; orient them start -> goal.
    const bool a_is_start = a == &from_start;
    Path head = (a_is_start ? *a : *b).pathTo(a_is_start ? meet_a : meet_b);
    Path tail = (a_is_start ? *b : *a).pathTo(a_is_start ? meet_b : meet_a);
    std::reverse(tail.waypoints.begin(), tail.waypoints.end());
    result.path = std::move(head);
    // The meeting point is in both halves, except in the trivial case (start sees the goal).
    const std::size_t skip = result.path.waypoints.back() == tail.waypoints.front() ? 1 : 0;
    result.path.waypoints.insert(result.path.waypoints.end(), tail.waypoints.begin() + skip,
                                 tail.waypoints.end());
  }
  result.counters["iterations"] = iterations;
  result.counters["nodes"] = static_cast<double>(from_start.generated() + from_goal.generated());
  return ctx.finish(std::move(result), o);
}

}  // namespace cosim
