#pragma once
// `cosim run` for ground robots (URDF bases) and worlds with moving obstacles: plan (a team plan
// from a multi-robot planner, a single-agent path per robot, a navigator deciding step by step,
// or the given waypoints), time the plan, drive it in MuJoCo (sim/ground_simulation.h), evaluate
// (robot-robot and obstacle contacts, plan-vs-executed deviation, arrival times) and write the
// same files as a flight run. Quadrotors in the scenario fly over the robots in the same loop,
// each with its own plan, reference and flight controller from the scenario's `aerial` sections
// (run/quadrotor_pilots.h); contacts between them and the robots are collisions.
#include "run/run_pipeline.h"

namespace cosim {

// Throws InputError (at world.grid_map.cell) unless robots of `robot_radius` plus the planner's
// margin fit the cells of the scenario's grid map for a team plan of `connectivity` (4 or 8).
void checkRobotsFitGridMap(const Scenario& scenario, double robot_radius, int connectivity);

// True if the scenario is for this pipeline: a ground robot, or moving obstacles.
bool isGroundRun(const Scenario& scenario);

// Builds every planner the run of `scenario` would build (the team planner, navigator or
// single-agent planner of the robots, the quadrotors' planner), reading the parameters the run
// reads, so that an unknown planner or parameter is found without running: sweeps check each
// job with it before starting any. Throws InputError as the run would.
void checkRunPlanners(const Scenario& scenario);

// Throws InputError for bad input found late (unknown planner, bad parameters, a team planner
// named for the quadrotors, moving obstacles without ground robots or that the navigator's grid
// cannot represent).
RunSummary executeGroundRun(Scenario& scenario, const RunRequest& request);

}  // namespace cosim
