#pragma once
#include "experiments/bench/bench_section.h"
#include "sim/run_log.h"
#include "sim/scenario.h"

namespace cosim::bench {

// A 32-quadrotor team's video frame against a single vehicle's in the same world (the bundled
// swarm32 scenario's room), both from the overview camera at 1280x720 with every overlay:
// milliseconds per frame, their ratio (target: the team's within 2x), and where the team's frame
// time goes (scene update, overlays, rasterising, 2D annotations, read-back; geoms drawn); and
// the team drawn with every member's plan and reference (render.team_plans), as it was before.
Section benchTeamRender(bool quick);

// Each vehicle of `s` flies from its start to its goal in 20 s, logged at 100 Hz, weaving a
// little off the straight line; its plan is a grid staircase of 0.5 m cells, as a team planner's.
RunLog syntheticTeamLog(const Scenario& s);

}  // namespace cosim::bench
