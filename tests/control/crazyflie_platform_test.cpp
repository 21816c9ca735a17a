// The crazyflie-firmware thrust command path (control/crazyflie_platform.h): power distribution
// signs and values, battery compensation, capping, and the stabilizer clock.
#include "control/crazyflie_platform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "control/mixer.h"

namespace cosim {
namespace {

// The cf21_brushless geometry as sim/ reads it (models/cf21_brushless.xml): rotors at 0.050 m,
// rotor i at 45 + 90 i degrees, spins +1 -1 +1 -1, k_m / k_f = THRUST2TORQUE.
QuadrotorParams brushlessAirframe() {
  QuadrotorParams q;
  q.rotor_xy = QuadrotorParams::xLayout(0.050);
  q.torque_per_thrust = 0.00569278844371417;
  q.thrust_coefficient = 3.86e-8;
  q.max_rotor_speed = 2590.0;
  q.max_thrust = 3.86e-8 * 2590.0 * 2590.0;
  return q;
}

TEST(CrazyfliePlatform, ForceTorqueMixMakesTheCommandedWrenchOnTheSimulatedAirframe) {
  // Hand case: T = 0.4 N, tau_x = 1e-3 N m. The lever is 0.05 / sqrt 2 = 0.0353553 m, so the
  // roll part is 0.25 1e-3 / 0.0353553 = 0.0070711 N: M1 and M2 (right side) 0.1 - 0.0070711,
  // M3 and M4 (left) 0.1 + 0.0070711.
  const CrazyfliePlatform p = crazyflie21BrushlessPlatform();
  const Eigen::Vector4d f = crazyflieForceTorqueMix(p, 0.4, {1e-3, 0.0, 0.0});
  EXPECT_NEAR(f[0], 0.0929289, 1e-7);
  EXPECT_NEAR(f[1], 0.0929289, 1e-7);
  EXPECT_NEAR(f[2], 0.1070711, 1e-7);
  EXPECT_NEAR(f[3], 0.1070711, 1e-7);
  // Any command: the firmware's motors, put on cosim's rotors, make exactly that wrench (signs of
  // roll, pitch and yaw, and the motor order, all at once).
  const Mixer mixer(brushlessAirframe());
  const Eigen::Vector3d tau(2e-4, -3e-4, 1.5e-4);
  const Eigen::Vector4d w =
      mixer.wrench(crazyflieToRotorOrder(crazyflieForceTorqueMix(p, 0.37, tau)));
  EXPECT_NEAR(w[0], 0.37, 1e-12);
  EXPECT_NEAR(w[1], tau.x(), 1e-12);
  EXPECT_NEAR(w[2], tau.y(), 1e-12);
  EXPECT_NEAR(w[3], tau.z(), 1e-12);
}

TEST(CrazyfliePlatform, LegacyMixReadsTheSixteenBitScaleAndTheFirmwareSigns) {
  const CrazyfliePlatform p = crazyflie21BrushlessPlatform();
  // Thrust 30000 (the PID's THRUST_BASE) is 30000 / 65535 x THRUST_MAX 0.2 = 0.0915541 N a motor.
  const Eigen::Vector4d hover = crazyflieLegacyMix(p, 30000, 0, 0, 0);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(hover[i], 0.0915541, 1e-7);
  const Mixer mixer(brushlessAirframe());
  const auto torque = [&](double r, double q, double y) {
    return mixer.wrench(crazyflieToRotorOrder(crazyflieLegacyMix(p, 30000, r, q, y)))
        .tail<3>()
        .eval();
  };
  // Roll +1000: half on each motor, 500 / 65535 x 0.2 N = 1.52590e-3 N, left up, right down:
  // tau_x = 4 x 1.525902e-3 x 0.03535534 = 2.157952e-4 N m.
  EXPECT_NEAR(torque(1000, 0, 0).x(), 2.157952e-4, 1e-9);
  EXPECT_LT(torque(0, 1000, 0).y(), 0.0);  // legacy pitch +: nose up, a negative torque about y
  EXPECT_LT(torque(0, 0, 1000).z(), 0.0);  // legacy yaw +: clockwise seen from above
}

TEST(CrazyfliePlatform, BatteryCompensationDeliversTheForceAndCappingKeepsTheDifferences) {
  const CrazyfliePlatform p = crazyflie21BrushlessPlatform();
  const double max_thrust = 3.86e-8 * 2590.0 * 2590.0;  // 0.258933 N
  const CrazyflieMotors motors(p, max_thrust);
  bool capped = true;
  const Eigen::Vector4d in(0.0907, 0.12, 0.05, 0.2);
  EXPECT_LT((motors.deliver(in, &capped) - in).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_FALSE(capped);
  // Below THRUST_MIN (0.0213626 N) a motor is off.
  EXPECT_EQ(motors.deliver({0.02, 0.1, 0.1, 0.1}, &capped)[0], 0.0);
  // Full duty is the rotors' maximum: V(0.258933) = 3.597681 V on the thrust curve. Asking
  // 0.3 N of M1 (V = 3.885220) overshoots by 0.287539 V; every motor drops by that: M1 gets
  // 0.258933 N, the 0.2 N motors T(3.125655 - 0.287539) = 0.168798 N.
  const Eigen::Vector4d out = motors.deliver({0.3, 0.2, 0.2, 0.2}, &capped);
  EXPECT_TRUE(capped);
  EXPECT_NEAR(out[0], max_thrust, 1e-9);
  EXPECT_NEAR(out[1], 0.168798, 1e-6);
  EXPECT_NEAR(out[3], 0.168798, 1e-6);
  // Without a rotor speed limit nothing is capped.
  const CrazyflieMotors unlimited(p, std::numeric_limits<double>::infinity());
  EXPECT_NEAR(unlimited.deliver({0.3, 0.2, 0.2, 0.2}, &capped)[0], 0.3, 1e-9);
  EXPECT_FALSE(capped);
}

TEST(CrazyfliePlatform, ThrustCurveInverseIsTheRootToTheLastBits) {
  const CrazyflieMotors motors(crazyflie21BrushlessPlatform(), 0.3);
  // The worked value above: 3.597681 V makes the rotors' maximum, 3.86e-8 x 2590^2 N.
  EXPECT_NEAR(motors.voltageForThrust(3.86e-8 * 2590.0 * 2590.0), 3.597681, 1e-6);
  // Across the motor's range (THRUST_MIN to beyond the cap) the voltage found makes the thrust
  // asked for to within a few ulps: a solver stopped early or started below the root would not.
  for (double v = 0.9; v < 5.0; v += 0.037) {
    const double thrust = motors.thrustAtVoltage(v);
    EXPECT_NEAR(motors.voltageForThrust(thrust), v, 1e-12) << v;
  }
  // Below the curve's value at 0 V no voltage makes the thrust: the motor is off.
  EXPECT_EQ(motors.voltageForThrust(-0.02), 0.0);
}

TEST(CrazyfliePlatform, ClockRunsEachPartAtItsFirmwareRate) {
  // Called at 500 Hz: the 500 Hz law every call, the 100 Hz parts every fifth, from the first.
  CrazyflieClock c;
  c.reset();
  int att = 0, pos = 0;
  for (int i = 0; i < 50; ++i) {
    c.advance(0.002);
    att += c.due(500.0);
    pos += c.due(100.0);
    if (i == 0) {
      EXPECT_TRUE(c.due(100.0));
    }
    if (i == 1) {
      EXPECT_FALSE(c.due(100.0));
    }
  }
  EXPECT_EQ(att, 50);
  EXPECT_EQ(pos, 10);
  // Called at 1000 Hz: the law every other call.
  c.reset();
  att = pos = 0;
  for (int i = 0; i < 100; ++i) {
    c.advance(0.001);
    att += c.due(500.0);
    pos += c.due(100.0);
  }
  EXPECT_EQ(att, 50);
  EXPECT_EQ(pos, 10);
}

}  // namespace
}  // namespace cosim
