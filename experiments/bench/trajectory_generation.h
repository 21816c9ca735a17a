#pragma once
#include "experiments/bench/bench_section.h"

namespace cosim::bench {

// Minimum-snap generation time for 10, 50 and 200 waypoints with NLopt time allocation against the
// closed-form fit with distance-proportional times (what the allocation costs, and what it buys
// in flight time under the same limits); and the geometric controller's time per control step
// against the cascade controller's. Target: 50 waypoints in under 50 ms.
Section benchTrajectoryGeneration(bool quick);

}  // namespace cosim::bench
