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

// One RRT* solve: the tree, the goal node once there is a path, and the counters.
class RrtStarRun {
 public:
  RrtStarRun(SamplingContext& ctx, const RrtStarOptions& options, bool planar)
      : ctx_(ctx),
        options_(options),
        o_(options.common),
        fixed_nodes_(options.max_tree_nodes > 0),
        planar_(planar),
        tree_(initialCapacity(o_), o_.linear_scan),
        goal_(ctx.goal()),
        root_(tree_.add(ctx.start(), SamplingTree::kNone, 0.0)) {
    if (ctx.start() == goal_) goal_node_ = root_;
    offerGoal(root_);
  }

  // Samples until the context says stop.
  void run() {
    while (!ctx_.shouldStop(o_, tree_.generated(), solved())) iterate();
  }

  PlanResult result() const {
    PlanResult result;
    if (solved()) result.path = tree_.pathTo(goal_node_);
    result.counters["iterations"] = iterations_;
    result.counters["nodes"] = static_cast<double>(tree_.generated());
    result.counters["tree_nodes"] = static_cast<double>(tree_.size());
    result.counters["rewires"] = rewires_;
    if (solved()) result.counters["first_path_nodes"] = first_path_nodes_;
    // The goal's cost-to-come as the tree holds it: the path's length unless rewired costs were
    // not passed on (rewire_costs: node), when it keeps an older, longer value.
    if (solved()) result.counters["goal_cost"] = tree_.cost(goal_node_);
    if (fixed_nodes_) result.counters["removed_nodes"] = removed_;
    if (solved() && o_.mode == 2 &&
        (o_.max_nodes == 0 || tree_.generated() < static_cast<std::size_t>(o_.max_nodes)))
      result.counters["stopped_by_time_limit"] = 1;
    return result;
  }

 private:
  bool solved() const { return goal_node_ != SamplingTree::kNone; }

  // One sample: steer towards it, choose the parent, add the node, rewire, try the goal.
  void iterate() {
    ++iterations_;
    if (fixed_nodes_ && tree_.size() > static_cast<std::size_t>(options_.max_tree_nodes))
      removed_ += leaves_.removeOne(tree_, root_, goal_node_, goal_) ? 1 : 0;

    const bool solved_before = solved();
    const double c_best = solved_before ? tree_.cost(goal_node_) : 0.0;
    // Once solved, goal samples can no longer extend the tree towards the goal usefully.
    const double bias = solved_before ? 0.0 : o_.goal_bias;
    const bool informed = options_.informed && solved_before;
    const Eigen::Vector3d target = informed ? ctx_.sampleInformed(bias, c_best) : ctx_.sample(bias);
    const std::uint32_t nearest = tree_.index().nearest(target);
    const Eigen::Vector3d& from = tree_.position(nearest);
    const Eigen::Vector3d x_new = SamplingContext::steer(from, target, o_.step);
    if (x_new == from) return;
    const double d_nearest = (x_new - from).norm();
    if (informed && tree_.cost(nearest) + d_nearest + (goal_ - x_new).norm() >= c_best)
      return;  // cannot lie on a better path (and saves a collision check)
    if (!ctx_.segmentFree(from, x_new)) return;

    collectNear(x_new, nearest, d_nearest);
    std::uint32_t parent = nearest;
    double cost_new = tree_.cost(nearest) + d_nearest;
    if (options_.choose_parent == ChooseParent::NearestParent)
      chooseNearestParent(x_new, nearest, parent, cost_new);
    else
      chooseCheapestParent(x_new, parent, cost_new);
    if (informed && cost_new + (goal_ - x_new).norm() >= c_best) return;
    const std::uint32_t id = tree_.add(x_new, parent, cost_new);
    if (fixed_nodes_) leaves_.push(tree_, id, goal_);
    if (x_new == goal_) {
      if (!solved()) first_path_nodes_ = static_cast<double>(tree_.generated());
      goal_node_ = id;
    }
    rewire(id, parent, cost_new, x_new);
    offerGoal(id);
  }

  // The near set (fixed radius or k nearest) of x_new, the nearest node always among them, for
  // choose-parent and rewiring.
  void collectNear(const Eigen::Vector3d& x_new, std::uint32_t nearest, double d_nearest) {
    if (options_.rewire_radius > 0.0) {
      tree_.index().withinRadius(x_new, options_.rewire_radius, found_);
    } else {
      // k-nearest RRT* (Karaman & Frazzoli 2011, sec. 3.3): k = e (1 + 1/d) log n neighbours.
      const double n = static_cast<double>(tree_.size() + 1);
      const double dim = planar_ ? 2.0 : 3.0;
      tree_.index().nearestK(
          x_new, static_cast<std::size_t>(std::ceil(M_E * (1.0 + 1.0 / dim) * std::log(n))),
          found_);
    }
    near_.clear();
    bool has_nearest = false;
    for (const auto& [id, d2] : found_) {
      const double d = std::sqrt(d2);
      near_.push_back({id, d, tree_.cost(id) + d, id == nearest ? 1 : -1});
      has_nearest |= id == nearest;
    }
    if (!has_nearest) near_.push_back({nearest, d_nearest, tree_.cost(nearest) + d_nearest, 1});
  }

  // Seed 003 Fig. 16: join x_new to x_old, the parent of its nearest node, if x_old is one of the
  // near nodes (within the thesis's "maximum allowed distance for optimisation") and sees it; by
  // the triangle inequality that is never dearer than through the nearest. (Without the distance
  // bound the rule chains back through the ancestors: in open space every node would join the
  // root and the paths would be any-angle straight lines.)
  void chooseNearestParent(const Eigen::Vector3d& x_new, std::uint32_t nearest,
                           std::uint32_t& parent, double& cost_new) {
    const std::uint32_t x_old = tree_.parent(nearest);
    auto in_near =
        std::find_if(near_.begin(), near_.end(), [&](const Neighbor& n) { return n.id == x_old; });
    if (x_old == SamplingTree::kNone || in_near == near_.end()) return;
    const double d_old = in_near->distance;
    if (in_near->free < 0) in_near->free = ctx_.segmentFree(tree_.position(x_old), x_new) ? 1 : 0;
    if (in_near->free == 1) {
      parent = x_old;
      cost_new = tree_.cost(x_old) + d_old;
    }
  }

  // Karaman-Frazzoli choose-parent: the neighbour giving the least cost-to-come through a free
  // edge; sorting the candidates by that cost first means only edges up to the winner are checked.
  void chooseCheapestParent(const Eigen::Vector3d& x_new, std::uint32_t& parent, double& cost_new) {
    std::sort(near_.begin(), near_.end(), [](const Neighbor& a, const Neighbor& b) {
      return a.cost_through != b.cost_through ? a.cost_through < b.cost_through : a.id < b.id;
    });
    std::size_t best = 0;
    for (; best < near_.size(); ++best) {
      Neighbor& n = near_[best];
      if (n.free < 0) n.free = ctx_.segmentFree(tree_.position(n.id), x_new) ? 1 : 0;
      if (n.free == 1) break;
    }
    // The nearest node's edge is free, so some candidate always wins.
    parent = near_[best].id;
    cost_new = near_[best].cost_through;
  }

  // Rewire: neighbours that get cheaper through the new node `id` take it as their parent.
  void rewire(std::uint32_t id, std::uint32_t parent, double cost_new,
              const Eigen::Vector3d& x_new) {
    for (Neighbor& n : near_) {
      if (n.id == parent || (!options_.reattach_goal && n.id == goal_node_)) continue;
      const double c = cost_new + n.distance;
      if (c >= tree_.cost(n.id)) continue;
      if (n.free < 0) n.free = ctx_.segmentFree(tree_.position(n.id), x_new) ? 1 : 0;
      if (n.free == 0) continue;
      const std::uint32_t old_parent = tree_.parent(n.id);
      tree_.reparent(n.id, id, c, options_.propagate_rewire_costs);
      ++rewires_;
      if (fixed_nodes_ && tree_.isLeaf(old_parent)) leaves_.push(tree_, old_parent, goal_);
    }
  }

  // Connects node `id` to the goal if that is shorter than the current path (or the first one).
  void offerGoal(std::uint32_t id) {
    const Eigen::Vector3d& p = tree_.position(id);
    const double d = (goal_ - p).norm();
    if (id == goal_node_ || d > o_.goal_tolerance) return;
    const double c = tree_.cost(id) + d;
    if (solved() && (!options_.reattach_goal || c >= tree_.cost(goal_node_))) return;
    if (!ctx_.segmentFree(p, goal_)) return;
    if (!solved()) {
      goal_node_ = tree_.add(goal_, id, c);
      first_path_nodes_ = static_cast<double>(tree_.generated());
    } else {
      const std::uint32_t old_parent = tree_.parent(goal_node_);
      tree_.reparent(goal_node_, id, c, options_.propagate_rewire_costs);
      if (fixed_nodes_ && tree_.isLeaf(old_parent)) leaves_.push(tree_, old_parent, goal_);
    }
  }

  SamplingContext& ctx_;
  const RrtStarOptions& options_;
  const SamplingOptions& o_;
  const bool fixed_nodes_, planar_;
  SamplingTree tree_;
  FarthestLeafQueue leaves_;
  const Eigen::Vector3d goal_;
  const std::uint32_t root_;
  std::uint32_t goal_node_ = SamplingTree::kNone;
  double first_path_nodes_ = 0;  // nodes generated when the first path appeared
  std::vector<std::pair<std::uint32_t, double>> found_;
  std::vector<Neighbor> near_;
  double iterations_ = 0, rewires_ = 0, removed_ = 0;
};

}  // namespace

std::string RrtStar::name() const {
  if (options_.informed) return "informed_rrt_star";
  if (options_.choose_parent == ChooseParent::NearestParent) return "rrt_star_thesis";
  return options_.max_tree_nodes > 0 ? "rrt_star_fn" : "rrt_star";
}

PlanResult RrtStar::solve(const PlanningProblem& problem, const StopToken& stop) {
  SamplingContext ctx(problem, stop);
  if (!ctx.invalid().empty()) return ctx.reject();
  RrtStarRun run(ctx, options_, problem.planar);
  run.run();
  return ctx.finish(run.result(), options_.common);
}

}  // namespace cosim
