#pragma once
// Plans a team of quadrotors jointly (the pipeline of Hoenig et al., "Trajectory planning for
// quadrotor swarms", T-RO 2018, with a grid for their roadmap): a 3D grid whose pitch comes from
// the separation ellipsoid (team_grid.h), starts and goals snapped to it, one MAPF solution on it
// from a team planner (planning/mapf: lacam or pibt on a 3D grid), and each agent's cell sequence
// refined into a minimum-snap trajectory that keeps the separation and the clearance in
// continuous time (team_trajectories.h). Starts or goals that the grid cannot hold (two in one
// cell, one in a blocked cell, or moves onto the cells closer than the separation) are planned
// on a roadmap finer than the ellipsoid with ellipsoid conflicts instead (dense_roadmap.h,
// dense_team_search.h), then smoothed the same way.
//
// Every agent first moves from its start to its start cell's centre (one step, all together),
// then follows the plan, waits at its goal cell's centre until the last one has arrived, and moves
// to its goal in one last common step: inside its own cell, away from everyone else's.
#include <Eigen/Core>
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "planning/mapf/mapf_planner.h"
#include "planning/team/team_trajectories.h"
#include "planning/world/world.h"

namespace cosim {

struct TeamAgent {
  Eigen::Vector3d start = Eigen::Vector3d::Zero(), goal = Eigen::Vector3d::Zero();
  SeparationEllipsoid separation;
  double inflation = 0.0;  // m the grid keeps clear of obstacles: radius + margin
  double clearance = 0.0;  // m the smoothed trajectory keeps clear: radius + half the margin
};

struct TeamPlanningProblem {
  const World* world = nullptr;
  std::vector<TeamAgent> agents;
  // The ellipsoidal distance the plan keeps between any two agents (1: the ellipsoid's surface);
  // above 1 it is the flight's budget for tracking error. The grid's pitch grows with it.
  double min_separation = 1.5;
  double max_speed = 1.0;         // m/s, for the step duration
  double max_acceleration = 2.0;  // m/s^2, for the step duration
  double time_limit_s = 30.0;     // for the whole team plan: grid, MAPF search and smoothing
  std::uint64_t seed = 1;
  // Repairs asked for by a flight of an earlier plan of the same team
  // (run/team_plan_verification.h): per agent, the waypoints (step indices) at which it must come
  // to rest, so that it flies the lock-step moves there; and a factor on the step time (a slower
  // team).
  std::vector<std::vector<long>> rest_steps;
  double step_stretch = 1.0;
  const std::atomic<bool>* stop = nullptr;
  // A line for a person following a long plan (the stage reached, repair rounds); may be empty.
  std::function<void(const std::string&)> progress;
};

struct TeamPlan {
  bool success = false;
  PlannerStatus status = PlannerStatus::Unknown;  // the MAPF search's, then the smoothing's
  std::string message;                            // why not, on failure
  // Per agent: its position at every step (start, cell centres, goal) and its trajectory.
  std::vector<std::vector<Eigen::Vector3d>> points;
  std::vector<PiecewisePolynomialTrajectory> trajectories;
  double time_ms = 0.0;  // grid, MAPF search and smoothing
  // The MAPF planner's counters plus grid_cells, blocked_cells, pitch_xy_m, pitch_z_m,
  // step_duration_s, sum_of_costs, makespan, mapf_ms, smoothing_ms, repair_rounds, stops_added,
  // planned_min_separation.
  std::map<std::string, double> counters;
};

// The lock-step time per grid step: a rest-to-rest minimum-snap move over the longer pitch within
// max_speed and max_acceleration (peak speed 35/16 and peak acceleration 7.51 times distance over
// time, resp. its square, for the 7th-degree rest-to-rest polynomial).
double teamStepDuration(const Eigen::Vector3d& pitch, double max_speed, double max_acceleration);

// Throws InputError (place "vehicles[i].start" / ".goal", file left empty) when two starts or
// goals are closer than min_separation, or no dense roadmap holds them (dense_roadmap.h).
TeamPlan planQuadrotorTeam(const TeamPlanningProblem& problem, MapfPlanner& planner);

}  // namespace cosim
