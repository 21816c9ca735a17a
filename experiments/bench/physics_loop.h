#pragma once
#include "experiments/bench/bench_section.h"

namespace cosim::bench {

// Bare mj_step throughput against the full simulation loop (physics + controller + logging +
// contact bookkeeping, no rendering) on the same model: the loop must keep >= 80%.
Section benchPhysicsLoop(bool quick);
// The same with what the realism issue added between physics and controller: motion-capture
// sensing, an IMU and the error-state EKF (the controller sees the estimate). Target >= 60%.
Section benchSensingLoop(bool quick);

}  // namespace cosim::bench
