#pragma once
// Smooth trajectories for a team planned in lock-step on a grid (a MAPF solution: every agent
// moves one cell or waits at each step), keeping each pair outside its separation ellipsoid and
// each vehicle clear of obstacles in continuous time: the continuous refinement stage of Hoenig
// et al., "Trajectory planning for quadrotor swarms" (T-RO 2018), done here by check and repair
// rather than by their constrained optimisation.
//
// Each agent's cell centres at the steps become waypoints at t = k * step. Between the waypoints
// where it stops (its start, its goal, wherever it waits) it flies one minimum-snap polynomial
// through the waypoints (MinimumSnapClosedForm, every segment one step long), so it keeps to the
// schedule and passes straight runs without slowing down, cutting corners a little. The team is
// then sampled every check_interval; wherever two agents come closer than min_separation (or one
// closer to an obstacle than its clearance), both are made to stop at the waypoints around that
// instant, and refitted, until nothing is violated.
//
// The check goes window by window (one step each): the pairs checked in a window are those a
// spatial hash of the window finds near each other (team_pair_candidates.h), and after a repair
// only the windows where some refitted trajectory actually changed are checked again, so a
// round costs what the repair touched, not agents squared times instants. It polls the stop
// token at every instant and trajectory fit: a stop request or the time limit ends it within
// milliseconds. This terminates: an agent that stops at
// every waypoint flies the grid path itself, each segment with the same rest-to-rest time law, so
// the whole team moves as the lock-step plan interpolated linearly, which the grid's spacing
// keeps apart (sim/ chooses a pitch of sqrt(2) separations: two agents in adjacent cells, one
// moving into the cell the other is leaving at right angles, are one separation apart at worst).
#include <Eigen/Core>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/stop_token.h"
#include "planning/planner_status.h"
#include "planning/team/separation_ellipsoid.h"
#include "planning/trajectory/piecewise_polynomial_trajectory.h"
#include "planning/world/world.h"

namespace cosim {

struct TeamMember {
  std::vector<Eigen::Vector3d> points;  // the agent's position at t = k * step; then it holds
  SeparationEllipsoid separation;
  double clearance = 0.0;  // m between its centre and any obstacle surface
  // Waypoints (step indices) where it rests from the start, besides its ends and waits: where a
  // flight of an earlier plan broke the separation (run/team_plan_verification.h).
  std::vector<long> rest_steps;
};

struct TeamTrajectoryOptions {
  double step_duration = 1.0;    // s per grid step
  double min_separation = 1.0;   // ellipsoidal distance to keep (1: the ellipsoid's surface)
  double check_interval = 0.02;  // s between checked instants
  int max_repair_rounds = 500;
  const StopToken* deadline = nullptr;  // the team planning's time limit and stop request
  // Called after each repair round (round, windows checked this round, windows in all, agents
  // refitted): for a progress line on long plans.
  std::function<void(int, int, int, int)> progress;
};

struct TeamTrajectories {
  bool success = false;
  PlannerStatus status = PlannerStatus::Unknown;
  std::string message;                                      // why not, on failure
  std::vector<PiecewisePolynomialTrajectory> trajectories;  // one per member
  // At the checked instants; 1.5 x options.min_separation when no pair came that close (the
  // spatial hash's reach: a lower bound).
  double min_separation = std::numeric_limits<double>::infinity();
  double min_clearance = std::numeric_limits<double>::infinity();  // m beyond the clearance
  int repair_rounds = 0;
  int stops_added = 0;   // waypoints where an agent was made to stop
  long pair_checks = 0;  // pair distances evaluated (pairs x instants, over all rounds)
};

TeamTrajectories smoothTeamPaths(const std::vector<TeamMember>& team, const World& world,
                                 const TeamTrajectoryOptions& options);

}  // namespace cosim
