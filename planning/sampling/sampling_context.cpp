#include "planning/sampling/sampling_context.h"

#include <cstdio>

#include "planning/sampling/path_shortcutter.h"

namespace cosim {

namespace {

std::string describe(const char* what, const Eigen::Vector3d& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s (%g, %g, %g)", what, p.x(), p.y(), p.z());
  return buf;
}

const World& worldOf(const PlanningProblem& problem) {
  static const World empty;
  return problem.world ? *problem.world : empty;
}

}  // namespace

SamplingContext::SamplingContext(const PlanningProblem& problem, const StopToken& stop)
    : world_(worldOf(problem), problem.inflation, problem.inflation, problem.planar),
      sampler_(world_.validMin(), world_.validMax(), problem.planar, problem.start.z()),
      deadline_(problem.time_limit_s, stop),
      rng_(problem.seed),
      start_(problem.start),
      goal_(problem.goal),
      time_limit_s_(problem.time_limit_s) {
  if (problem.planar) goal_.z() = start_.z();
  char inflated[64];
  std::snprintf(inflated, sizeof inflated, " (obstacles inflated by %g m)", problem.inflation);
  if (!problem.world) {
    invalid_ = "no world given";
    invalid_status_ = PlannerStatus::InvalidProblem;
  } else if (!world_.insideBounds(start_)) {
    invalid_ = describe("start", start_) + " is outside the world bounds";
    invalid_status_ = PlannerStatus::InvalidStart;
  } else if (!world_.insideBounds(goal_)) {
    invalid_ = describe("goal", goal_) + " is outside the world bounds";
    invalid_status_ = PlannerStatus::InvalidGoal;
  } else if (!world_.pointFree(start_)) {
    invalid_ = describe("start", start_) + " is inside an obstacle" + inflated;
    invalid_status_ = PlannerStatus::InvalidStart;
  } else if (!world_.pointFree(goal_)) {
    invalid_ = describe("goal", goal_) + " is inside an obstacle" + inflated;
    invalid_status_ = PlannerStatus::InvalidGoal;
  }
}

Eigen::Vector3d SamplingContext::sample(double goal_bias) {
  if (goal_bias > 0.0 && std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < goal_bias)
    return goal_;
  return sampler_.uniform(rng_);
}

Eigen::Vector3d SamplingContext::sampleInformed(double goal_bias, double c_best) {
  if (goal_bias > 0.0 && std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < goal_bias)
    return goal_;
  return sampler_.informed(start_, goal_, c_best, rng_);
}

Eigen::Vector3d SamplingContext::steer(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                       double step) {
  const Eigen::Vector3d d = to - from;
  const double dist = d.norm();
  if (dist <= step) return to;
  return from + d * (step / dist);
}

bool SamplingContext::shouldStop(const SamplingOptions& o, std::size_t generated,
                                 bool solved) const {
  const int budget = o.max_nodes > 0 ? o.max_nodes : kNodeMemoryBound;
  if (generated >= static_cast<std::size_t>(budget) || deadline_.expired()) return true;
  if (!solved) return false;
  return o.mode == 1 || deadline_.elapsedMs() >= 1000.0 * o.improve_time_s;
}

PlanResult SamplingContext::reject() const {
  PlanResult result;
  result.message = invalid_;
  result.status = invalid_status_;
  result.counters["collision_checks"] = collision_checks_;
  result.time_ms = deadline_.elapsedMs();
  return result;
}

PlanResult SamplingContext::finish(PlanResult result, const SamplingOptions& o) {
  result.success = !result.path.empty();
  result.status = searchStatus(result.success, deadline_, PlannerStatus::LimitReached);
  if (result.success) {
    result.message.clear();
    if (o.shortcut) {
      const std::size_t before = result.path.size();
      result.path = shortcutPath(
          result.path,
          [this](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return segmentFree(a, b); });
      result.counters["shortcut_removed_waypoints"] =
          static_cast<double>(before - result.path.size());
    }
  } else {
    // Why: which limit stopped the search, after how much work, for how large a vehicle.
    const double nodes = result.counters.count("nodes") ? result.counters.at("nodes") : 0.0;
    char why[192];
    if (deadline_.expired())
      std::snprintf(why, sizeof why, "time limit (%g s) reached after %.0f nodes without a path",
                    time_limit_s_, nodes);
    else if (o.max_nodes > 0)
      std::snprintf(why, sizeof why, "no path within max_nodes = %d", o.max_nodes);
    else
      std::snprintf(why, sizeof why, "no path within %d nodes (the memory bound)",
                    kNodeMemoryBound);
    char inflated[96];
    std::snprintf(inflated, sizeof inflated, " (obstacles inflated by %g m, step %g m)",
                  world_.inflation(), o.step);
    result.message = std::string(why) + inflated;
  }
  result.counters["collision_checks"] = collision_checks_;
  result.time_ms = deadline_.elapsedMs();
  return result;
}

}  // namespace cosim
