#pragma once
#include "experiments/bench/bench_section.h"

namespace cosim::bench {

// Bare mj_step throughput against the full simulation loop (physics + controller + logging +
// contact bookkeeping, no rendering) on the same model: the loop must keep >= 80%.
Section benchPhysicsLoop(bool quick);

}  // namespace cosim::bench
