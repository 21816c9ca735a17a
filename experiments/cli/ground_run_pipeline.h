#pragma once
// `cosim run` for ground robots (URDF bases) and worlds with moving obstacles: plan (a team plan
// from a multi-robot planner, a single-agent path per robot, a navigator deciding step by step,
// or the given waypoints), time the plan, drive it in MuJoCo (sim/ground_simulation.h), evaluate
// (robot-robot and obstacle contacts, plan-vs-executed deviation, arrival times) and write the
// same files as a flight run.
#include "experiments/cli/run_pipeline.h"

namespace cosim {

// True if the scenario is for this pipeline: a ground robot, or moving obstacles.
bool isGroundRun(const Scenario& scenario);

// Throws InputError for bad input found late (unknown planner, bad parameters, a team plan
// asked of quadrotors, moving obstacles the navigator's grid cannot represent).
RunSummary executeGroundRun(Scenario& scenario, const RunRequest& request);

}  // namespace cosim
