#pragma once
// A scenario's quadrotors planned jointly by a team planner (planner.name lacam or pibt; a 3D grid
// from their separation ellipsoids, planning/team/quadrotor_team_planner.h), each with its own
// timed minimum-snap trajectory that keeps the team apart. Used by `cosim run` when every vehicle
// is a quadrotor and planner.name names a multi-robot planner.
#include <cstddef>
#include <string>
#include <vector>

#include "control/quadrotor_params.h"
#include "core/param_set.h"
#include "planning/trajectory/piecewise_polynomial_trajectory.h"
#include "run/run_pipeline.h"
#include "run/scenario_planning.h"
#include "sim/world_model.h"

namespace cosim {

// The defaults of a team's parameters besides the MAPF planner's own.
constexpr double kTeamMinSeparation = 1.5;    // planner.min_separation, ellipsoidal distance
constexpr double kTeamMaxSpeed = 2.0;         // trajectory.max_speed, m/s
constexpr double kTeamMaxAcceleration = 3.0;  // trajectory.max_acceleration, m/s^2

// What flights of an earlier plan of the team asked of its next plan
// (run/team_plan_verification.h).
struct TeamRepairs {
  std::vector<std::vector<long>> rest_steps;  // per member: waypoints where it comes to rest
  double step_stretch = 1.0;                  // a factor on the lock-step's step time
  double min_separation = 0.0;  // ellipsoids the plan keeps at least (0: the settings')
};

struct QuadrotorTeamFlight {
  bool success = false;
  std::string failure;             // "no path found: ..." on failure
  std::vector<VehiclePlan> plans;  // one per quadrotor; the first carries the team's time
  std::vector<PiecewisePolynomialTrajectory> trajectories;
};

// Reads what a team run reads of planner.* and builds its MAPF planner, so that sweeps find bad
// parameters before running (throws InputError as the run would).
void checkQuadrotorTeamPlanner(const Scenario& scenario);

// Plans scenario.vehicles[v] (flying world.vehicles()[v]) for each v in `vehicles` as one team,
// with the planner and trajectory of `sections` (its controller sets the team's separation) and
// the repairs asked for. The team is slowed (its step time stretched) until no member's
// trajectory asks for more than scenario.team.max_thrust_fraction of its thrust, the downwash of
// the members above counted (run/team_thrust.h), with `airframes[k]` the believed airframe of
// vehicles[k]. Throws InputError for bad parameters, or starts and goals the team's grid cannot
// hold.
QuadrotorTeamFlight planQuadrotorTeamFlight(const Scenario& scenario,
                                            const MotionSections& sections, const WorldModel& world,
                                            const std::vector<std::size_t>& vehicles,
                                            const std::vector<QuadrotorParams>& airframes,
                                            const RunRequest& request,
                                            const TeamRepairs& repairs = {});

}  // namespace cosim
