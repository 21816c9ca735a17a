#include "planning/sampling/rrt_star.h"

#include <algorithm>
#include <cmath>
#include <queue>

#include "planning/sampling/sampling_tree.h"

namespace cosim {

namespace {

// A neighbour of the new node: its id, distance to the new node, cost through it, and whether
// the edge was found free (1), blocked (0) or not checked yet (-1). Choose-parent fills the
// verdicts that rewiring then reuses (the edge is the same in both directions).
struct Neighbor {
  std::uint32_t id;
  double distance;
  double cost_through;
  int free;
};

// RRT*FN removal policy of seed 003: the childless node farthest from the goal. Leaves are kept
// in a max-heap by distance to the goal; entries that stopped being removable leaves are
// skipped when they reach the top (lazy deletion).
class FarthestLeafQueue {
 public:
  void push(const SamplingTree& tree, std::uint32_t id, const Eigen::Vector3d& goal) {
    heap_.emplace((tree.position(id) - goal).squaredNorm(), id);
  }
  // Removes one removable leaf from the tree; false if there is none.
  bool removeOne(SamplingTree& tree, std::uint32_t root, std::uint32_t goal_node,
                 const Eigen::Vector3d& goal) {
    while (!heap_.empty()) {
      const std::uint32_t id = heap_.top().second;
      heap_.pop();
      if (id == root || id == goal_node || !tree.alive(id) || !tree.isLeaf(id)) continue;
      const std::uint32_t parent = tree.parent(id);
      tree.removeLeaf(id);
      if (tree.isLeaf(parent)) push(tree, parent, goal);
      return true;
    }
    return false;
  }

 private:
  std::priority_queue<std::pair<double, std::uint32_t>> heap_;
};

}  // namespace

std::string RrtStar::name() const {
  if (options_.informed) return "informed_rrt_star";
  if (options_.choose_parent == ChooseParent::NearestParent) return "rrt_star_thesis";
  return options_.max_tree_nodes > 0 ? "rrt_star_fn" : "rrt_star";
}

PlanResult RrtStar::solve(const PlanningProblem& problem) {
  SamplingContext ctx(problem);
  if (!ctx.invalid().empty()) return ctx.reject();
  const SamplingOptions& o = options_.common;
  const bool fixed_nodes = options_.max_tree_nodes > 0;
  SamplingTree tree(initialCapacity(o), o.linear_scan);
  FarthestLeafQueue leaves;
  const Eigen::Vector3d& goal = ctx.goal();
  const std::uint32_t root = tree.add(ctx.start(), SamplingTree::kNone, 0.0);
  std::uint32_t goal_node = SamplingTree::kNone;
  if (ctx.start() == goal) goal_node = root;
  double first_path_nodes = 0;  // nodes generated when the first path appeared

  // Connects node `id` to the goal if that is shorter than the current path (or the first one).
  auto offerGoal = [&](std::uint32_t id) {
    const Eigen::Vector3d& p = tree.position(id);
    const double d = (goal - p).norm();
    if (id == goal_node || d > o.goal_tolerance) return;
    const double c = tree.cost(id) + d;
    if (goal_node != SamplingTree::kNone && c >= tree.cost(goal_node)) return;
    if (!ctx.segmentFree(p, goal)) return;
    if (goal_node == SamplingTree::kNone) {
      goal_node = tree.add(goal, id, c);
      first_path_nodes = static_cast<double>(tree.generated());
    } else {
      const std::uint32_t old_parent = tree.parent(goal_node);
      tree.reparent(goal_node, id, c);
      if (fixed_nodes && tree.isLeaf(old_parent)) leaves.push(tree, old_parent, goal);
    }
  };
  offerGoal(root);

  std::vector<std::pair<std::uint32_t, double>> found;
  std::vector<Neighbor> near;
  double iterations = 0, rewires = 0, removed = 0;
  while (!ctx.shouldStop(o, tree.generated(), goal_node != SamplingTree::kNone)) {
    ++iterations;
    if (fixed_nodes && tree.size() > static_cast<std::size_t>(options_.max_tree_nodes))
      removed += leaves.removeOne(tree, root, goal_node, goal) ? 1 : 0;

    const bool solved = goal_node != SamplingTree::kNone;
    const double c_best = solved ? tree.cost(goal_node) : 0.0;
    // Once solved, goal samples can no longer extend the tree towards the goal usefully.
    const double bias = solved ? 0.0 : o.goal_bias;
    const Eigen::Vector3d target =
        options_.informed && solved ? ctx.sampleInformed(bias, c_best) : ctx.sample(bias);
    const std::uint32_t nearest = tree.index().nearest(target);
    const Eigen::Vector3d& from = tree.position(nearest);
    const Eigen::Vector3d x_new = SamplingContext::steer(from, target, o.step);
    if (x_new == from) continue;
    const double d_nearest = (x_new - from).norm();
    if (options_.informed && solved &&
        tree.cost(nearest) + d_nearest + (goal - x_new).norm() >= c_best)
      continue;  // cannot lie on a better path (and saves a collision check)
    if (!ctx.segmentFree(from, x_new)) continue;

    // The near set (fixed radius or k nearest), for choose-parent and rewiring. Karaman-Frazzoli
    // choose-parent takes the neighbour giving the least cost-to-come through a free edge;
    // sorting the candidates by that cost first means only edges up to the winner are checked.
    if (options_.rewire_radius > 0.0) {
      tree.index().withinRadius(x_new, options_.rewire_radius, found);
    } else {
      // k-nearest RRT* (Karaman & Frazzoli 2011, sec. 3.3): k = e (1 + 1/d) log n neighbours.
      const double n = static_cast<double>(tree.size() + 1);
      const double dim = problem.planar ? 2.0 : 3.0;
      tree.index().nearestK(
          x_new, static_cast<std::size_t>(std::ceil(M_E * (1.0 + 1.0 / dim) * std::log(n))), found);
    }
    near.clear();
    bool has_nearest = false;
    for (const auto& [id, d2] : found) {
      const double d = std::sqrt(d2);
      near.push_back({id, d, tree.cost(id) + d, id == nearest ? 1 : -1});
      has_nearest |= id == nearest;
    }
    if (!has_nearest) near.push_back({nearest, d_nearest, tree.cost(nearest) + d_nearest, 1});
    std::uint32_t parent = nearest;
    double cost_new = tree.cost(nearest) + d_nearest;
    if (options_.choose_parent == ChooseParent::NearestParent) {
      // Seed 003 Fig. 16: join x_new to x_old, the parent of its nearest node, if x_old is one
      // of the near nodes (within the thesis's "maximum allowed distance for optimisation")
      // and sees it; by the triangle inequality that is never dearer than through the nearest.
      // (Without the distance bound the rule chains back through the ancestors: in open space
      // every node would join the root and the paths would be any-angle straight lines.)
      const std::uint32_t x_old = tree.parent(nearest);
      auto in_near =
          std::find_if(near.begin(), near.end(), [&](const Neighbor& n) { return n.id == x_old; });
      if (x_old != SamplingTree::kNone && in_near != near.end()) {
        const double d_old = in_near->distance;
        if (in_near->free < 0) in_near->free = ctx.segmentFree(tree.position(x_old), x_new) ? 1 : 0;
        if (in_near->free == 1) {
          parent = x_old;
          cost_new = tree.cost(x_old) + d_old;
        }
      }
    } else {
      std::sort(near.begin(), near.end(), [](const Neighbor& a, const Neighbor& b) {
        return a.cost_through != b.cost_through ? a.cost_through < b.cost_through : a.id < b.id;
      });
      std::size_t best = 0;
      for (; best < near.size(); ++best) {
        Neighbor& n = near[best];
        if (n.free < 0) n.free = ctx.segmentFree(tree.position(n.id), x_new) ? 1 : 0;
        if (n.free == 1) break;
      }
      // The nearest node's edge is free, so some candidate always wins.
      parent = near[best].id;
      cost_new = near[best].cost_through;
    }
    if (options_.informed && solved && cost_new + (goal - x_new).norm() >= c_best) continue;
    const std::uint32_t id = tree.add(x_new, parent, cost_new);
    if (fixed_nodes) leaves.push(tree, id, goal);
    if (x_new == goal) {
      if (goal_node == SamplingTree::kNone)
        first_path_nodes = static_cast<double>(tree.generated());
      goal_node = id;
    }

    // Rewire: neighbours that get cheaper through the new node take it as their parent.
    for (Neighbor& n : near) {
      if (n.id == parent) continue;
      const double c = cost_new + n.distance;
      if (c >= tree.cost(n.id)) continue;
      if (n.free < 0) n.free = ctx.segmentFree(tree.position(n.id), x_new) ? 1 : 0;
      if (n.free == 0) continue;
      const std::uint32_t old_parent = tree.parent(n.id);
      tree.reparent(n.id, id, c);
      ++rewires;
      if (fixed_nodes && tree.isLeaf(old_parent)) leaves.push(tree, old_parent, goal);
    }
    offerGoal(id);
  }

  PlanResult result;
  if (goal_node != SamplingTree::kNone) result.path = tree.pathTo(goal_node);
  result.counters["iterations"] = iterations;
  result.counters["nodes"] = static_cast<double>(tree.generated());
  result.counters["tree_nodes"] = static_cast<double>(tree.size());
  result.counters["rewires"] = rewires;
  if (goal_node != SamplingTree::kNone) result.counters["first_path_nodes"] = first_path_nodes;
  if (fixed_nodes) result.counters["removed_nodes"] = removed;
  if (goal_node != SamplingTree::kNone && o.mode == 2 &&
      (o.max_nodes == 0 || tree.generated() < static_cast<std::size_t>(o.max_nodes)))
    result.counters["stopped_by_time_limit"] = 1;
  return ctx.finish(std::move(result), o);
}

}  // namespace cosim
