#include "control/ground_controller.h"

#include <cmath>
#include <stdexcept>

namespace cosim {

void GroundMotionLimits::validate() const {
  if (!(max_speed > 0) || !(max_acceleration > 0) || !(max_yaw_rate > 0) ||
      !(max_yaw_acceleration > 0))
    throw std::invalid_argument("ground motion limits must be positive");
}

double wrapAngle(double a) {
  a = std::remainder(a, 2.0 * M_PI);
  return a <= -M_PI ? a + 2.0 * M_PI : a;
}

bool stepTowards(Eigen::Vector2d& current, const Eigen::Vector2d& target, double max_step) {
  const Eigen::Vector2d d = target - current;
  const double n = d.norm();
  if (n <= max_step) {
    current = target;
    return false;
  }
  current += d * (max_step / n);
  return true;
}

bool stepTowards(double& current, double target, double max_step) {
  const double d = target - current;
  if (std::abs(d) <= max_step) {
    current = target;
    return false;
  }
  current += d > 0 ? max_step : -max_step;
  return true;
}

}  // namespace cosim
