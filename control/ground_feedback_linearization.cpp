#include "control/ground_feedback_linearization.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cosim {

GroundFeedbackLinearization::GroundFeedbackLinearization(GroundMotionLimits limits,
                                                         GroundFeedbackLinearizationParams params)
    : limits_(limits), p_(params) {
  limits_.validate();
  if (!(p_.b > 0) || !(p_.k > 0) || !(p_.wheel_separation > 0))
    throw std::invalid_argument(
        "feedback linearisation: b, k and the wheel separation must be positive");
}

void GroundFeedbackLinearization::reset() {
  v_ = w_ = 0.0;
}

GroundCommand GroundFeedbackLinearization::update(const PlanarState& x, const PlanarReference& r,
                                                  double dt) {
  GroundCommand c;
  const Eigen::Vector2d heading(std::cos(x.yaw), std::sin(x.yaw));
  const double ref_speed = r.velocity.norm();
  const Eigen::Vector2d ref_heading =
      ref_speed > 1e-6 ? Eigen::Vector2d(r.velocity / ref_speed) : heading;
  const Eigen::Vector2d b_point = x.position + p_.b * heading;
  const Eigen::Vector2d b_ref = r.position + p_.b * ref_heading;
  const Eigen::Vector2d u = r.velocity + p_.k * (b_ref - b_point);
  double v = heading.dot(u);
  double w = (-heading.y() * u.x() + heading.x() * u.y()) / p_.b;

  // One common factor keeps the curvature w / v: speed, yaw rate, and each wheel's speed.
  double scale = 1.0;
  if (std::abs(v) > limits_.max_speed) scale = std::min(scale, limits_.max_speed / std::abs(v));
  if (std::abs(w) > limits_.max_yaw_rate)
    scale = std::min(scale, limits_.max_yaw_rate / std::abs(w));
  const double wheel = std::abs(v) + 0.5 * p_.wheel_separation * std::abs(w);
  if (wheel > limits_.max_speed) scale = std::min(scale, limits_.max_speed / wheel);
  c.saturated = scale < 1.0;
  v *= scale;
  w *= scale;
  c.saturated |= stepTowards(v_, v, limits_.max_acceleration * dt);
  c.saturated |= stepTowards(w_, w, limits_.max_yaw_acceleration * dt);
  // The rate limits move v and w separately; the wheels must still stay within their speed.
  const double wheels = std::abs(v_) + 0.5 * p_.wheel_separation * std::abs(w_);
  if (wheels > limits_.max_speed) {
    v_ *= limits_.max_speed / wheels;
    w_ *= limits_.max_speed / wheels;
    c.saturated = true;
  }
  c.forward = v_;
  c.yaw_rate = w_;
  return c;
}

}  // namespace cosim
