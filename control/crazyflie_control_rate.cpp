#include "control/crazyflie_control_rate.h"

#include <cmath>

namespace cosim {

std::string crazyflieControlRateProblem(const std::string& name, double rate_hz) {
  if (name.rfind("crazyflie_", 0) != 0) return "";
  const double ratio = rate_hz / 500.0;
  if (ratio >= 1.0 && std::abs(ratio - std::round(ratio)) < 1e-9) return "";
  return "= " + std::to_string(rate_hz) + " Hz: " + name +
         " runs the firmware's 500 Hz stabilizer loop and needs a control rate that is a multiple "
         "of 500 Hz";
}

}  // namespace cosim
