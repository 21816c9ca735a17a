#include "control/mixer.h"

#include <gtest/gtest.h>

using namespace cosim;

namespace {
QuadrotorParams quad() {
  QuadrotorParams p;
  p.rotor_xy = QuadrotorParams::xLayout(0.225);
  p.torque_per_thrust = 0.016;
  p.min_thrust = 0.0;
  p.max_thrust = 6.0;
  return p;
}
}  // namespace

TEST(Mixer, AllocationAndWrenchAreExactInverses) {
  const Mixer mixer(quad());
  const Eigen::Vector3d torque(0.12, -0.07, 0.015);
  const Eigen::Vector4d u = mixer.allocate(14.7, torque);
  const Eigen::Vector4d w = mixer.wrench(u);
  EXPECT_NEAR(w[0], 14.7, 1e-12);
  EXPECT_NEAR(w[1], 0.12, 1e-12);
  EXPECT_NEAR(w[2], -0.07, 1e-12);
  EXPECT_NEAR(w[3], 0.015, 1e-12);
}

TEST(Mixer, PureThrustIsSharedEquallyAndRollTorqueLiftsTheLeftRotors) {
  const Mixer mixer(quad());
  const Eigen::Vector4d hover = mixer.allocate(12.0, Eigen::Vector3d::Zero());
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(hover[i], 3.0, 1e-12);
  // Positive roll torque (about +x) needs more thrust on the left (+y) rotors 0 and 1:
  // tau_x = sum y_i u_i with y = +-0.1591 m, so each left rotor gains tau / (4 * 0.1591).
  const Eigen::Vector4d roll = mixer.allocate(12.0, {0.2, 0.0, 0.0});
  const double delta = 0.2 / (4 * 0.225 / std::sqrt(2.0));
  EXPECT_NEAR(roll[0], 3.0 + delta, 1e-9);
  EXPECT_NEAR(roll[1], 3.0 + delta, 1e-9);
  EXPECT_NEAR(roll[2], 3.0 - delta, 1e-9);
  EXPECT_NEAR(roll[3], 3.0 - delta, 1e-9);
}

TEST(Mixer, SaturationGivesUpYawBeforeRollPitchAndThrust) {
  const Mixer mixer(quad());
  bool saturated = false;
  // Near-full thrust plus roll and a large yaw demand: roll and thrust must survive.
  const Eigen::Vector3d torque(0.3, 0.0, 0.2);
  const Eigen::Vector4d u = mixer.allocateLimited(18.0, torque, &saturated);
  EXPECT_TRUE(saturated);
  EXPECT_LE(u.maxCoeff(), 6.0 + 1e-12);
  EXPECT_GE(u.minCoeff(), 0.0 - 1e-12);
  const Eigen::Vector4d w = mixer.wrench(u);
  EXPECT_NEAR(w[1], 0.3, 1e-9);    // roll torque kept exactly
  EXPECT_NEAR(w[0], 18.0, 1e-9);   // thrust kept exactly
  EXPECT_LT(w[3], 0.2);            // yaw reduced
  EXPECT_GT(w[3], 0.0);            // ... but not reversed
}

TEST(Mixer, UnsaturatedRequestIsDeliveredUnchanged) {
  const Mixer mixer(quad());
  bool saturated = true;
  const Eigen::Vector4d u = mixer.allocateLimited(14.0, {0.05, 0.02, 0.01}, &saturated);
  EXPECT_FALSE(saturated);
  EXPECT_TRUE(u.isApprox(mixer.allocate(14.0, {0.05, 0.02, 0.01}), 1e-12));
}
