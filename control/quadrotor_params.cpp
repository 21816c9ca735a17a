#include "control/quadrotor_params.h"

#include <algorithm>
#include <cmath>

namespace cosim {

double QuadrotorParams::rotorSpeedFor(double thrust) const {
  const double w = std::sqrt(std::max(thrust, 0.0) / thrust_coefficient);
  return std::clamp(w, min_rotor_speed, max_rotor_speed);
}

double QuadrotorParams::steadyRotorSpeed(double duty, double battery_voltage) const {
  const Eigen::Vector3d& c = motor_speed_map;
  const double v = duty * battery_voltage;
  return std::clamp(c[0] + v * (c[1] + v * c[2]), min_rotor_speed, max_rotor_speed);
}

double QuadrotorParams::hoverRotorSpeed() const {
  return rotorSpeedFor(mass * gravity / 4.0);
}

Eigen::Vector3d QuadrotorParams::linearDragPerMass() const {
  const double d = 4.0 * hoverRotorSpeed() * rotor_drag_coefficient / mass;
  return {d, d, 0.0};
}

std::array<Eigen::Vector2d, 4> QuadrotorParams::xLayout(double arm) {
  std::array<Eigen::Vector2d, 4> xy;
  for (int i = 0; i < 4; ++i) {
    const double a = (45.0 + 90.0 * i) * M_PI / 180.0;
    xy[i] = arm * Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  return xy;
}

}  // namespace cosim
