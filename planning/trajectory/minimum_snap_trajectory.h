#pragma once
// From a planner's path to a dynamically feasible, collision-checked reference trajectory:
//   1. thin the waypoints (duplicates, straight runs, and with a world, line-of-sight shortcuts);
//   2. fit the minimum-snap polynomial through them (MinimumSnapClosedForm), starting and ending at
//      rest, with segment times optimised by NLopt for snap cost + k_T x total time
//      (Mellinger and Kumar 2011);
//   3. scale time uniformly so the sampled speed, acceleration and thrust meet the limits;
//   4. with a world: where a piece comes within `inflation` of an obstacle, add the midpoint of
//      that piece's straight path segment as a waypoint and refit (Richter, Bry and Roy 2013,
//      Sec. 6), until clear or `max_repair_rounds` is reached; then report failure rather than a
//      trajectory through a wall.
#include <map>
#include <string>

#include "planning/path.h"
#include "planning/planner_status.h"
#include "planning/trajectory/piecewise_polynomial_trajectory.h"
#include "planning/trajectory/trajectory_limits.h"
#include "planning/world/world.h"

namespace cosim {

struct MinimumSnapOptions {
  TrajectoryLimits limits;
  // k_T, m^2/s^8: the price of one second of flight against snap cost. It sets the pace only
  // when `fill_limits` is off (see segment_time_allocation.h).
  double time_penalty = 100.0;
  bool optimize_times = true;  // false: durations proportional to segment length
  // true: time is scaled so that the binding limit is reached exactly (as fast as the limits
  // allow); false: only slowed down where a limit is exceeded.
  bool fill_limits = true;
  double collinear_tolerance = 0.01;  // m, see dropCollinearWaypoints
  bool shortcut = true;               // line-of-sight shortcuts (only with a world)
  // m: shortcuts must clear obstacles by this much more than `inflation`, leaving the curve room.
  double shortcut_margin = 0.1;
  int max_repair_rounds = 12;
  int samples_per_piece = 24;  // for the limit check
  int max_evaluations = 400;   // NLopt cost evaluations per fit

  // Throws InputError (file "trajectory") for values no fit can use.
  void validate() const;
};

struct MinimumSnapResult {
  bool success = false;
  // ExactSolution, LimitReached (still colliding after max_repair_rounds), InvalidProblem (an
  // empty path) or Stopped (a stop request, core/stop_request.h, ended the fit).
  PlannerStatus status = PlannerStatus::Unknown;
  PiecewisePolynomialTrajectory trajectory;  // also on failure: the last attempt, for display
  Path waypoints;                            // the waypoints it passes through, in order
  std::string message;                       // why it failed; empty on success
  // input_waypoints, thinned_waypoints, final_waypoints, repair_rounds, cost_evaluations,
  // snap_cost, duration_s, time_scale, peak_speed, peak_acceleration, peak_thrust_accel, time_ms
  std::map<std::string, double> counters;
};

class MinimumSnapTrajectory {
 public:
  explicit MinimumSnapTrajectory(const MinimumSnapOptions& options = {});
  const MinimumSnapOptions& options() const { return options_; }

  // In free space: no shortcuts, no collision check.
  MinimumSnapResult fit(const Path& path) const;
  // In `world` for a vehicle needing `inflation` metres of clearance (distance to an obstacle
  // <= inflation is a collision). `via`: indices of path points the curve must pass through
  // (waypoints the user asked to visit); thinning and shortcuts work between them, never past
  // them. The path's ends are always kept.
  MinimumSnapResult fit(const Path& path, const World& world, double inflation,
                        const std::vector<std::size_t>& via = {}) const;

 private:
  MinimumSnapResult fitImpl(const Path& path, const World* world, double inflation,
                            const std::vector<std::size_t>& via) const;
  // Step 1: duplicates, straight runs and (with a world) line-of-sight shortcuts, leg by leg.
  std::vector<Eigen::Vector3d> thinWaypoints(const Path& path, const World* world, double inflation,
                                             const std::vector<std::size_t>& via) const;
  MinimumSnapOptions options_;
};

}  // namespace cosim
