#pragma once
#include "experiments/bench/bench_section.h"

namespace cosim::bench {

// A 32-quadrotor team's video frame against a single vehicle's in the same world (the bundled
// swarm32 scenario's room), both from the overview camera at 1280x720 with every overlay:
// milliseconds per frame, their ratio (target: the team's within 2x), and where the team's frame
// time goes (scene update, overlays, rasterising, 2D annotations, read-back; geoms drawn); and
// the team drawn with every member's plan and reference (render.team_plans), as it was before.
Section benchTeamRender(bool quick);

}  // namespace cosim::bench
