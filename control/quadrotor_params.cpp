#include "control/quadrotor_params.h"

#include <cmath>

namespace cosim {

std::array<Eigen::Vector2d, 4> QuadrotorParams::xLayout(double arm) {
  std::array<Eigen::Vector2d, 4> xy;
  for (int i = 0; i < 4; ++i) {
    const double a = (45.0 + 90.0 * i) * M_PI / 180.0;
    xy[i] = arm * Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  return xy;
}

}  // namespace cosim
