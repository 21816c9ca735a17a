#pragma once
// The control rates the Crazyflie firmware's controllers can run at, checked where the scenario is
// read (kept apart from the controllers so the scenario reader does not link them).
#include <string>

namespace cosim {

// The firmware's stabilizer runs its controllers at 500 Hz: sim.control_rate must be a multiple
// of it. An empty string if `rate_hz` suits `name` (or `name` is no crazyflie_* controller), else
// why not.
std::string crazyflieControlRateProblem(const std::string& name, double rate_hz);

}  // namespace cosim
