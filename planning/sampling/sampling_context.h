#pragma once
// What every sampling planner needs during one solve(): the problem checked (start and goal in
// bounds and free), the inflated collision world, the random generator seeded from the problem,
// the deadline, collision-check counting, goal-biased sampling, steering and the final result.
#include <Eigen/Core>
#include <algorithm>
#include <limits>
#include <random>
#include <string>

#include "core/stop_token.h"
#include "planning/planner.h"
#include "planning/sampling/collision_world.h"
#include "planning/sampling/state_sampler.h"

namespace cosim {

// Parameters shared by the whole family (each planner reads the ones it uses; see
// sampling_planners.cpp for names, defaults and where the defaults come from).
struct SamplingOptions {
  double step = 2.0;  // maximum edge length ("maximum distance between nodes")
  // Budget of generated nodes N; 0 = none: the planner runs until its time limit (as OMPL's),
  // within kNodeMemoryBound.
  int max_nodes = 0;
  // 1: stop at the first solution; 2 (anytime): keep improving until max_nodes (when set) or
  // improve_time_s.
  int mode = 1;
  // Mode 2: seconds after the start of solve() at which improving stops (the anytime planners'
  // `time_limit`); the search for a first solution runs on to the problem's own time limit.
  double improve_time_s = std::numeric_limits<double>::infinity();
  double goal_bias = 0.05;      // probability of sampling the goal itself
  double goal_tolerance = 0.0;  // new nodes this close to the goal try to connect to it
  bool shortcut = false;        // greedy shortcutting of the returned path
  bool linear_scan = false;     // nearest-neighbour queries by scanning every node (seed 003's)
};

// Nodes one solve() may generate at most, set or not: bounds memory (about 1 GB).
constexpr int kNodeMemoryBound = 10000000;
// How many nodes a planner's arrays reserve at first (they grow beyond it when needed).
inline std::size_t initialCapacity(const SamplingOptions& o) {
  return o.max_nodes > 0
             ? std::min<std::size_t>(static_cast<std::size_t>(o.max_nodes) + 2, 1u << 18)
             : std::size_t(1) << 14;
}

class SamplingContext {
 public:
  // The deadline is the problem's time limit inside the caller's `stop`.
  SamplingContext(const PlanningProblem& problem, const StopToken& stop);

  // Why the problem cannot be planned (start/goal outside bounds or in collision), or empty.
  const std::string& invalid() const { return invalid_; }

  const Eigen::Vector3d& start() const { return start_; }
  // For planar problems the goal is projected onto the plane z = start.z.
  const Eigen::Vector3d& goal() const { return goal_; }
  const CollisionWorld& world() const { return world_; }
  std::mt19937_64& rng() { return rng_; }
  bool timeUp() const { return deadline_.expired(); }
  // Whether a planner's loop ends now: the problem's time limit, the node budget (max_nodes if
  // set, else kNodeMemoryBound), or once `solved`, mode 1 at once and mode 2 at improve_time_s.
  bool shouldStop(const SamplingOptions& o, std::size_t generated, bool solved) const;

  bool pointFree(const Eigen::Vector3d& p) {
    ++collision_checks_;
    return world_.pointFree(p);
  }
  bool segmentFree(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    ++collision_checks_;
    return world_.segmentFree(a, b);
  }

  // The goal with probability goal_bias, otherwise a uniform state.
  Eigen::Vector3d sample(double goal_bias);
  // Informed sample for the current best cost c_best (Gammell et al. 2014), with goal bias.
  Eigen::Vector3d sampleInformed(double goal_bias, double c_best);
  // The point at most `step` from `from` towards `to` (Steer of seed 003 / LaValle 1998).
  static Eigen::Vector3d steer(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double step);

  // Fills time, collision_checks, success and message; shortcuts the path if asked. An empty
  // path means failure: the message then says what stopped the search (the time limit or
  // max_nodes) after how many nodes, and the inflation the obstacles were grown by.
  PlanResult finish(PlanResult result, const SamplingOptions& o);
  // A failure before any search: invalid() is the message (start or goal invalid).
  PlanResult reject() const;

 private:
  CollisionWorld world_;
  StateSampler sampler_;
  StopToken deadline_;
  std::mt19937_64 rng_;
  Eigen::Vector3d start_, goal_;
  double time_limit_s_;
  std::string invalid_;
  PlannerStatus invalid_status_ = PlannerStatus::Unknown;
  double collision_checks_ = 0;
};

}  // namespace cosim
