// Ground-robot controllers and timed paths, without physics (kinematic models integrated here).
#include <gtest/gtest.h>

#include <cmath>

#include "control/ground_feedback_linearization.h"
#include "control/ground_timed_path.h"
#include "control/ground_velocity_tracker.h"

namespace cosim {
namespace {

TEST(GroundTimedPath, SmoothedReversalStaysWithinAccelerationAndCutsByQuarterOfVH) {
  // 0.5 m/s out and straight back: a velocity jump of 1 m/s at t = 2.
  GroundTimedPath p;
  p.append(0.0, {0, 0});
  p.append(2.0, {1, 0});
  p.append(4.0, {0, 0});
  const double h = 0.5 / 1.0;  // v / a
  p.setSmoothing(h);
  double peak_accel = 0.0, farthest = 0.0;
  for (double t = 0.0; t < 4.6; t += 0.01) {
    const double a = (p.sample(t + 0.005).velocity - p.sample(t - 0.005).velocity).norm() / 0.01;
    peak_accel = std::max(peak_accel, a);
    farthest = std::max(farthest, p.sample(t).position.x());
  }
  EXPECT_NEAR(peak_accel, 1.0, 0.02);
  // The turn-around point falls short by v h / 4 = 0.125 m.
  EXPECT_NEAR(farthest, 1.0 - 0.125, 1e-3);
  EXPECT_TRUE(p.sample(4.5).final);
  EXPECT_FALSE(p.sample(4.49).final);
}

TEST(GroundVelocityTracker, HolonomicPointConvergesOntoMovingReference) {
  GroundMotionLimits limits;
  GroundVelocityTracker c(limits);
  PlanarState x;  // a perfect velocity servo: the state moves at the commanded velocity
  x.position = {0.3, -0.2};
  for (double t = 0; t < 5.0; t += 0.01) {
    PlanarReference r;
    r.position = {0.2 * t, 0.0};
    r.velocity = {0.2, 0.0};
    const GroundCommand cmd = c.update(x, r, 0.01);
    x.position += 0.01 * Eigen::Vector2d(cmd.forward, cmd.lateral);  // yaw stays 0
  }
  EXPECT_NEAR(x.position.x(), 0.2 * 5.0, 0.01);
  EXPECT_NEAR(x.position.y(), 0.0, 0.01);
}

TEST(GroundFeedbackLinearization, UnicycleStartingSidewaysTracksStraightLine) {
  GroundMotionLimits limits;
  limits.max_speed = 0.22;
  limits.max_yaw_rate = 2.75;
  GroundFeedbackLinearization c(limits, {0.08, 2.0, 0.16});
  PlanarState x;
  x.yaw = M_PI / 2;  // facing +y, the path runs along +x
  double worst_late = 0.0;
  for (double t = 0; t < 10.0; t += 0.01) {
    PlanarReference r;
    r.position = {0.1 * t, 0.0};
    r.velocity = {0.1, 0.0};
    const GroundCommand cmd = c.update(x, r, 0.01);
    x.position += 0.01 * cmd.forward * Eigen::Vector2d(std::cos(x.yaw), std::sin(x.yaw));
    x.yaw += 0.01 * cmd.yaw_rate;
    if (t > 6.0) worst_late = std::max(worst_late, (x.position - r.position).norm());
    EXPECT_LE(std::abs(cmd.forward) + 0.08 * std::abs(cmd.yaw_rate), 0.22 + 1e-9);  // wheel limit
  }
  EXPECT_LT(worst_late, 0.01);
  EXPECT_NEAR(x.yaw, 0.0, 0.05);
}

}  // namespace
}  // namespace cosim
