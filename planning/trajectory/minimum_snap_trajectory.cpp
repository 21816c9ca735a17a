#include "planning/trajectory/minimum_snap_trajectory.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/stop_token.h"
#include "core/input_error.h"
#include "planning/trajectory/inflated_world.h"
#include "planning/trajectory/minimum_snap_closed_form.h"
#include "planning/trajectory/segment_time_allocation.h"
#include "planning/trajectory/waypoint_thinning.h"

namespace cosim {
namespace {

// Waypoints closer than this are one waypoint (a zero-length segment has no duration to fit).
constexpr double kDuplicateDistance = 1e-6;  // m

std::string formatPoint(const Eigen::Vector3d& p) {
  std::ostringstream s;
  s.precision(3);
  s << std::fixed << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// One fit of `waypoints`: durations (optimised if asked, from `durations` or distance-
// proportional ones), the closed-form trajectory, scaled in time to the limits.
PiecewisePolynomialTrajectory fitOnce(const MinimumSnapOptions& options,
                                      const std::vector<Eigen::Vector3d>& waypoints,
                                      std::vector<double>& durations, int& evaluations,
                                      double& scale, const StopToken& clock) {
  const MinimumSnapClosedForm fit(waypoints);
  if (durations.empty()) durations = distanceProportionalTimes(fit, options.time_penalty);
  if (options.optimize_times) {
    TimeAllocationResult allocation =
        optimizeSegmentTimes(fit, durations, options.time_penalty, options.max_evaluations, &clock);
    durations = std::move(allocation.durations);
    evaluations += allocation.evaluations;
  }
  PiecewisePolynomialTrajectory trajectory = fit.trajectory(durations);
  scale = timeScaleForLimits(trajectory, options.limits, options.samples_per_piece);
  if (!options.fill_limits) scale = std::max(scale, 1.0);
  trajectory.scaleTime(scale);
  return trajectory;
}

// Why the fit gave up: where the trajectory still comes too close to an obstacle.
std::string stillCollidingMessage(const InflatedWorld& checker,
                                  const std::vector<Eigen::Vector3d>& waypoints,
                                  const InflatedWorld::Collision& c, double inflation, int round) {
  const bool segment_blocked = !checker.segmentClear(waypoints[c.piece], waypoints[c.piece + 1]);
  return "trajectory still within " + std::to_string(inflation) + " m of an obstacle at " +
         formatPoint(c.position) + " after " + std::to_string(round) + " repair rounds" +
         (segment_blocked
              ? " (the planned path segment " + formatPoint(waypoints[c.piece]) + " - " +
                    formatPoint(waypoints[c.piece + 1]) + " is itself not clear)"
              : "");
}

// Splits every colliding piece at the midpoint of its straight path segment; each half starts
// at half its duration.
void splitCollidingPieces(const std::vector<InflatedWorld::Collision>& collisions,
                          std::vector<Eigen::Vector3d>& waypoints, std::vector<double>& durations) {
  std::vector<Eigen::Vector3d> repaired;
  std::vector<double> repaired_durations;
  std::size_t next = 0;
  for (std::size_t i = 0; i + 1 < waypoints.size(); ++i) {
    repaired.push_back(waypoints[i]);
    if (next < collisions.size() && collisions[next].piece == i) {
      ++next;
      repaired.push_back(0.5 * (waypoints[i] + waypoints[i + 1]));
      repaired_durations.insert(repaired_durations.end(), 2, 0.5 * durations[i]);
    } else {
      repaired_durations.push_back(durations[i]);
    }
  }
  repaired.push_back(waypoints.back());
  waypoints = std::move(repaired);
  durations = std::move(repaired_durations);
}

}  // namespace

void MinimumSnapOptions::validate() const {
  limits.validate();
  const auto fail = [](const char* place, const std::string& problem) {
    throw InputError("trajectory", place, problem);
  };
  if (!(time_penalty > 0.0) || !std::isfinite(time_penalty)) fail("k_T", "must be finite and > 0");
  if (!(collinear_tolerance >= 0.0)) fail("collinear_tolerance", "must be >= 0");
  if (!(shortcut_margin >= 0.0)) fail("shortcut_margin", "must be >= 0");
  if (max_repair_rounds < 0) fail("max_repair_rounds", "must be >= 0");
  if (samples_per_piece < 2) fail("samples_per_piece", "must be >= 2");
  if (max_evaluations < 1) fail("max_evaluations", "must be >= 1");
}

MinimumSnapTrajectory::MinimumSnapTrajectory(const MinimumSnapOptions& options)
    : options_(options) {
  options_.validate();
}

MinimumSnapResult MinimumSnapTrajectory::fit(const Path& path) const {
  return fitImpl(path, nullptr, 0.0, {});
}

MinimumSnapResult MinimumSnapTrajectory::fit(const Path& path, const World& world, double inflation,
                                             const std::vector<std::size_t>& via) const {
  if (!(inflation >= 0.0)) throw InputError("trajectory", "inflation", "must be >= 0");
  return fitImpl(path, &world, inflation, via);
}

std::vector<Eigen::Vector3d> MinimumSnapTrajectory::thinWaypoints(
    const Path& path, const World* world, double inflation,
    const std::vector<std::size_t>& via) const {
  const std::size_t n = path.waypoints.size();
  if (n < 2) return path.waypoints;
  std::vector<std::size_t> keep{0};
  for (std::size_t i : via)
    if (i > 0 && i + 1 < n) keep.push_back(i);
  keep.push_back(n - 1);
  std::sort(keep.begin(), keep.end());
  keep.erase(std::unique(keep.begin(), keep.end()), keep.end());

  std::vector<Eigen::Vector3d> out;
  for (std::size_t j = 0; j + 1 < keep.size(); ++j) {
    std::vector<Eigen::Vector3d> leg(path.waypoints.begin() + static_cast<long>(keep[j]),
                                     path.waypoints.begin() + static_cast<long>(keep[j + 1]) + 1);
    leg = dropDuplicateWaypoints(leg, kDuplicateDistance);
    leg = dropCollinearWaypoints(leg, options_.collinear_tolerance);
    if (world && options_.shortcut) {
      const InflatedWorld wider(*world, inflation + options_.shortcut_margin, leg);
      leg = shortcutWaypoints(leg, wider);
    }
    // Consecutive legs share their joining point.
    out.insert(out.end(), leg.begin() + (out.empty() ? 0 : 1), leg.end());
  }
  // A via point on top of its neighbour would make a segment of zero length.
  return dropDuplicateWaypoints(out, kDuplicateDistance);
}

MinimumSnapResult MinimumSnapTrajectory::fitImpl(const Path& path, const World* world,
                                                 double inflation,
                                                 const std::vector<std::size_t>& via) const {
  // No time limit (a fit is bounded by its rounds and evaluations), but a stop request ends it.
  const StopToken clock(1e9);
  MinimumSnapResult result;
  result.counters["input_waypoints"] = static_cast<double>(path.size());
  if (path.empty()) {
    result.message = "empty path: nothing to fit";
    result.status = PlannerStatus::InvalidProblem;
    return result;
  }

  // 1. Thinning.
  std::vector<Eigen::Vector3d> waypoints = thinWaypoints(path, world, inflation, via);
  result.counters["thinned_waypoints"] = static_cast<double>(waypoints.size());

  if (waypoints.size() == 1) {  // start = goal: hold the point
    PolynomialPiece hold;
    hold.coefficients.row(0) = waypoints.front().transpose();
    result.trajectory = PiecewisePolynomialTrajectory({hold});
    result.waypoints.waypoints = waypoints;
    result.success = true;
    result.status = PlannerStatus::ExactSolution;
    result.counters["time_ms"] = clock.elapsedMs();
    return result;
  }

  const InflatedWorld* checker = nullptr;
  std::optional<InflatedWorld> inflated;
  if (world) {
    inflated.emplace(*world, inflation, waypoints);
    checker = &*inflated;
  }

  // 2.-4. Fit, scale, check, repair. Durations carry over between rounds (a split segment's
  // halves start at half its duration), so later rounds start near their optimum.
  std::vector<double> durations;
  int evaluations = 0;
  for (int round = 0;; ++round) {
    double scale = 1.0;
    result.trajectory = fitOnce(options_, waypoints, durations, evaluations, scale, clock);
    result.waypoints.waypoints = waypoints;
    result.counters["repair_rounds"] = round;
    result.counters["cost_evaluations"] = evaluations;
    result.counters["time_scale"] = scale;

    const std::vector<InflatedWorld::Collision> collisions =
        checker ? checker->collisions(result.trajectory) : std::vector<InflatedWorld::Collision>{};
    if (clock.stopRequested()) {
      result.status = PlannerStatus::Stopped;
      result.message = "stopped";
      break;
    }
    if (collisions.empty()) {
      result.success = true;
      result.status = PlannerStatus::ExactSolution;
      break;
    }
    if (round >= options_.max_repair_rounds) {
      result.status = PlannerStatus::LimitReached;
      result.message =
          stillCollidingMessage(*checker, waypoints, collisions.front(), inflation, round);
      break;
    }
    splitCollidingPieces(collisions, waypoints, durations);
  }

  const TrajectoryPeaks peaks =
      samplePeaks(result.trajectory, options_.limits.gravity, options_.samples_per_piece);
  result.counters["final_waypoints"] = static_cast<double>(waypoints.size());
  result.counters["snap_cost"] = result.trajectory.snapCost();
  result.counters["duration_s"] = result.trajectory.duration();
  result.counters["peak_speed"] = peaks.speed;
  result.counters["peak_acceleration"] = peaks.acceleration;
  result.counters["peak_thrust_accel"] = peaks.thrust_accel;
  result.counters["time_ms"] = clock.elapsedMs();
  return result;
}

}  // namespace cosim
