// The rotors' speed states: spin-up and spin-down follow their own time constants, thrust is
// k_f w^2, and speeds stay within the airframe's limits.
#include "sim/rotor_model.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace cosim;

namespace {

QuadrotorParams iris() {
  QuadrotorParams p;
  p.thrust_coefficient = 5.84e-6;
  p.min_rotor_speed = 100.0;
  p.max_rotor_speed = 1100.0;
  p.time_constant_up = 0.0125;
  p.time_constant_down = 0.025;
  return p;
}

// Time until a step from `from` to `to` covers 1 - 1/e of the way, stepping at 0.1 ms.
double timeToCover63(RotorModel& r, double from, double to) {
  r.reset(Eigen::Vector4d::Constant(from));
  r.command(Eigen::Vector4d::Constant(to));
  const double target = from + (1.0 - std::exp(-1.0)) * (to - from);
  double t = 0.0;
  while ((to - r.speeds()[0]) * (to > from ? 1 : -1) > (to - target) * (to > from ? 1 : -1)) {
    r.advance(1e-4);
    t += 1e-4;
  }
  return t;
}

}  // namespace

TEST(RotorModel, SpinsUpWithItsUpTimeConstantAndDownWithItsDownTimeConstant) {
  RotorModel r(iris());
  EXPECT_NEAR(timeToCover63(r, 400.0, 900.0), 0.0125, 2e-4);
  EXPECT_NEAR(timeToCover63(r, 900.0, 400.0), 0.025, 2e-4);
}

TEST(RotorModel, ThrustIsTheCoefficientTimesSpeedSquaredAndSpeedsStayInRange) {
  RotorModel r(iris());
  r.reset(Eigen::Vector4d(500.0, 50.0, 2000.0, 800.0));
  EXPECT_DOUBLE_EQ(r.speeds()[1], 100.0);   // below the minimum
  EXPECT_DOUBLE_EQ(r.speeds()[2], 1100.0);  // above the maximum
  EXPECT_NEAR(r.thrusts()[0], 5.84e-6 * 500.0 * 500.0, 1e-12);
  EXPECT_NEAR(r.thrusts()[2], 7.0664, 1e-4);  // the Iris' 7.07 N per rotor at full speed
  // A command beyond the range is clamped too, and a held command is reached exactly.
  r.command(Eigen::Vector4d::Constant(5000.0));
  for (int k = 0; k < 2000; ++k) r.advance(1e-3);
  EXPECT_NEAR(r.speeds()[0], 1100.0, 1e-9);
}

TEST(RotorModel, AMotorDelayHoldsTheOldCommandForExactlyThatLongThenLagsAsWithout) {
  QuadrotorParams p = iris();
  p.motor_delay = 0.008;
  RotorModel delayed(p);
  RotorModel immediate(iris());
  delayed.reset(Eigen::Vector4d::Constant(400.0));
  immediate.reset(Eigen::Vector4d::Constant(400.0));
  delayed.command(Eigen::Vector4d::Constant(900.0));
  // 8 steps of 1 ms: the delayed rotor has not moved yet.
  for (int k = 0; k < 8; ++k) delayed.advance(1e-3);
  EXPECT_DOUBLE_EQ(delayed.speeds()[0], 400.0);
  immediate.command(Eigen::Vector4d::Constant(900.0));
  // From then on both follow the same lag, step for step.
  for (int k = 0; k < 30; ++k) {
    delayed.advance(1e-3);
    immediate.advance(1e-3);
  }
  EXPECT_NEAR(delayed.speeds()[0], immediate.speeds()[0], 1e-9);
  EXPECT_GT(delayed.speeds()[0], 800.0);
}
