#include "control/ground_velocity_tracker.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cosim {

GroundVelocityTracker::GroundVelocityTracker(GroundMotionLimits limits,
                                             GroundVelocityTrackerGains gains)
    : limits_(limits), gains_(gains) {
  limits_.validate();
  if (!(gains_.k_position > 0) || !(gains_.k_yaw > 0))
    throw std::invalid_argument("velocity tracker gains must be positive");
}

void GroundVelocityTracker::reset() {
  velocity_.setZero();
  yaw_rate_ = 0.0;
}

GroundCommand GroundVelocityTracker::update(const PlanarState& x, const PlanarReference& r,
                                            double dt) {
  GroundCommand c;
  Eigen::Vector2d v = r.velocity + gains_.k_position * (r.position - x.position);
  if (v.norm() > limits_.max_speed) {
    v *= limits_.max_speed / v.norm();
    c.saturated = true;
  }
  c.saturated |= stepTowards(velocity_, v, limits_.max_acceleration * dt);
  double w = std::clamp(gains_.k_yaw * wrapAngle(r.yaw - x.yaw), -limits_.max_yaw_rate,
                        limits_.max_yaw_rate);
  c.saturated |= stepTowards(yaw_rate_, w, limits_.max_yaw_acceleration * dt);
  const double cy = std::cos(x.yaw), sy = std::sin(x.yaw);
  c.forward = cy * velocity_.x() + sy * velocity_.y();
  c.lateral = -sy * velocity_.x() + cy * velocity_.y();
  c.yaw_rate = yaw_rate_;
  return c;
}

}  // namespace cosim
