#pragma once
#include <string>

#include "experiments/bench/bench_section.h"

namespace cosim::bench {

// Flying a given reference must not slow the loop: the bundled crazyflie_figure8.yaml (the
// figure-eight, motion capture, the EKF, its controller) in the full loop against bare mj_step
// replaying the same flight; figure ratio_to_bare, target >= 0.8. Then the same with the other
// Crazyflie estimator (crazyflie_kalman if the scenario names ekf, else ekf): figures
// <name>_ratio_to_bare etc., the same target.
Section benchReferenceFlight(bool quick);
// The same under the controller `controller` (a name the controller factory knows) instead of
// the scenario's.
Section measureReferenceFlight(bool quick, const std::string& controller);

}  // namespace cosim::bench
