#include "control/crazyflie_thrust_path.h"

#include <gtest/gtest.h>

#include "control/crazyflie_lee_controller.h"
#include "control/crazyflie_pid_controller.h"
#include "control/quadrotor_params.h"

namespace cosim {
namespace {

// The cf21_brushless airframe's motor map and thrust constant (models/cf21_brushless.xml).
QuadrotorParams brushlessMotor() {
  QuadrotorParams q;
  q.thrust_coefficient = 3.86e-8;
  q.min_rotor_speed = 0.0;
  q.max_rotor_speed = 2590.0;
  q.motor_speed_map = {-137.43, 1283.97, -115.943};
  return q;
}

TEST(CrazyflieThrustPath, PwmQuadraticGivesTheForksPwmForAThrust) {
  // 0.0981 N is 10 g (thrustToPWM: N 1000 / 9.81): 0.16609668469985447 + 0.02297914810965436 10
  // + 0.0001878280261464696 100 = 0.414670968, i.e. PWM 27175.46 of 65535.
  const double duty = pwmQuadraticDuty(kImrcForkPwmQuadratic, 0.0981);
  EXPECT_NEAR(duty, 0.41467096841104506, 1e-12);
  EXPECT_NEAR(duty * 65535.0, 27175.4619, 1e-3);
  // No force: PWM 0 (then the idle thrust's floor).
  EXPECT_EQ(pwmQuadraticDuty(kImrcForkPwmQuadratic, 0.0), 0.0);
}

TEST(CrazyflieThrustPath, CapDropsEveryMotorByTheExcessAndFloorsAtIdle) {
  bool capped = false;
  const Eigen::Vector4d d = capCrazyflieDuties({1.1, 0.5, 0.2, 0.05}, 10000.0 / 65535.0, &capped);
  EXPECT_TRUE(capped);
  EXPECT_NEAR(d[0], 1.0, 1e-12);
  EXPECT_NEAR(d[1], 0.4, 1e-12);
  EXPECT_NEAR(d[2], 10000.0 / 65535.0, 1e-12);  // 0.1 below idle
  EXPECT_NEAR(d[3], 10000.0 / 65535.0, 1e-12);
  capCrazyflieDuties({0.9, 0.5, 0.2, 0.3}, 0.0, &capped);
  EXPECT_FALSE(capped);
}

TEST(CrazyflieThrustPath, ForksDefaultsAreItsIdleThrustAndTheUpstreamBuildsIsZero) {
  CrazyflieThrustPath path;
  EXPECT_EQ(path.idleThrust(), 0.0);
  path.map = CrazyflieThrustMap::PwmQuadratic;
  EXPECT_EQ(path.idleThrust(), 10000.0);  // cfbl_defconfig CONFIG_MOTORS_DEFAULT_IDLE_THRUST
  path.idle_thrust = 6000.0;
  EXPECT_EQ(path.idleThrust(), 6000.0);
}

TEST(CrazyflieThrustPath, MixerWithCf2AndCf21blConstantsSplitsATorqueByHand) {
  // T = 0.36 N, tau = (1e-3, -5e-4, 1e-4) N m. f_i = T/4 -+ tau_x/(4 l/sqrt2) -+ tau_y/(4 l/sqrt2)
  // -+ tau_z/(4 k): cf21bl l = 0.050 m, k = 0.00569278844371417 m; cf2 l = 0.046 m,
  // k = 0.005964552 m.
  const Eigen::Vector3d tau(1e-3, -5e-4, 1e-4);
  const CrazyfliePlatform bl =
      crazyflieMixerConstants(crazyflie21BrushlessPlatform(), CrazyflieMixerPlatform::Cf21bl);
  const CrazyfliePlatform cf2 =
      crazyflieMixerConstants(crazyflie21BrushlessPlatform(), CrazyflieMixerPlatform::Cf2);
  const Eigen::Vector4d f_bl = crazyflieForceTorqueMix(bl, 0.36, tau);
  const Eigen::Vector4d f_cf2 = crazyflieForceTorqueMix(cf2, 0.36, tau);
  const Eigen::Vector4d want_bl(0.0820729450939141, 0.08378491928235494, 0.08914401290577957,
                                0.10499812271795138);
  const Eigen::Vector4d want_cf2(0.08196559873017853, 0.08266251472228783, 0.08965154200394534,
                                 0.10572034454358828);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(f_bl[i], want_bl[i], 1e-12) << i;
    EXPECT_NEAR(f_cf2[i], want_cf2[i], 1e-12) << i;
  }
  // Only the mixer's constants change: the thrust curve stays the build's.
  EXPECT_EQ(cf2.vmotor2thrust, crazyflie21BrushlessPlatform().vmotor2thrust);
}

TEST(CrazyflieThrustPath, WithoutCompensationHoverThrustDropsAsTheVoltageSags) {
  // 9.25 g a motor (a 37 g vehicle): duty 0.394724840. On the motor map w = c0 + c1 v + c2 v^2,
  // v = duty V: at 4.0 V, 1600.79 rad/s and k_f w^2 = 0.098914 N; at 3.7 V, 1490.48 rad/s and
  // 0.085751 N, 13 % less.
  const QuadrotorParams q = brushlessMotor();
  CrazyflieThrustPath path;
  path.map = CrazyflieThrustMap::PwmQuadratic;
  const CrazyflieMotors motors(crazyflie21BrushlessPlatform(), q.max_thrust);
  const double f = 0.037 * 9.81 / 4.0;
  for (const auto& [volts, speed, thrust] :
       {std::tuple{4.0, 1600.7924186951009, 0.09891390379521604},
        std::tuple{3.7, 1490.4776787238316, 0.08575081523587569}}) {
    const Eigen::Vector4d duty =
        crazyflieMotorDuties(path, motors, Eigen::Vector4d::Constant(f), volts, nullptr);
    EXPECT_NEAR(duty[0], 0.39472484020131465, 1e-12);
    EXPECT_NEAR(q.steadyRotorSpeed(duty[0], volts), speed, 1e-9);
    EXPECT_NEAR(q.thrust_coefficient * speed * speed, thrust, 1e-12);
  }
}

TEST(CrazyflieThrustPath, CompensationHoldsTheMotorVoltageAsTheBatterySags) {
  // battery_compensated: duty = v_motor(f) / V, so duty V, the rotor speed and the thrust do not
  // depend on V.
  const QuadrotorParams q = brushlessMotor();
  const CrazyflieThrustPath path;
  const CrazyflieMotors motors(crazyflie21BrushlessPlatform(), q.max_thrust);
  const Eigen::Vector4d f = Eigen::Vector4d::Constant(0.0907);
  const double v_motor = motors.voltageForThrust(0.0907);
  const Eigen::Vector4d at_high = crazyflieMotorDuties(path, motors, f, 4.1, nullptr);
  const Eigen::Vector4d at_low = crazyflieMotorDuties(path, motors, f, 3.6, nullptr);
  EXPECT_NEAR(at_high[0], v_motor / 4.1, 1e-12);
  EXPECT_NEAR(at_low[0], v_motor / 3.6, 1e-12);
  EXPECT_NEAR(q.steadyRotorSpeed(at_high[0], 4.1), q.steadyRotorSpeed(at_low[0], 3.6), 1e-9);
  // Below THRUST_MIN the motor is off (then idle, 0 for this build).
  EXPECT_EQ(crazyflieMotorDuties(path, motors, Eigen::Vector4d::Constant(0.01), 4.0, nullptr)[0],
            0.0);
}

TEST(CrazyflieThrustPath, ControllerOnABatteryOutputsDutiesAndWithoutOneThrusts) {
  QuadrotorParams q = brushlessMotor();
  q.mass = 0.037;
  q.gravity = 9.81;
  q.max_thrust = 3.86e-8 * 2590.0 * 2590.0;
  q.rotor_xy = QuadrotorParams::xLayout(0.05);
  q.torque_per_thrust = 0.00569278844371417;
  CrazyflieLeeController lee(q, CrazyflieLeeGains{});
  CrazyflieThrustPath path;
  path.map = CrazyflieThrustMap::PwmQuadratic;
  lee.setThrustPath(path);
  lee.reset();
  VehicleState s;
  s.position = {0, 0, 1};
  FlatReference ref;
  ref.position = {0, 0, 1};
  s.battery_voltage = 3.9;
  const ControlOutput out = lee.update(s, ref, 0.002);
  ASSERT_TRUE(out.drives_duty);
  // Hover, at rest on the reference: T = m g, 9.25 g a motor, the fork's duty 0.3947248.
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(out.motor_duty[i], 0.39472484020131465, 1e-9);
  s.battery_voltage = 0.0;  // pwm_quadratic cannot fly on an ideal supply
  lee.reset();
  EXPECT_THROW(lee.update(s, ref, 0.002), std::logic_error);
}

TEST(CrazyflieThrustPath, ForkSendsTheLegacyModesSixteenBitValuesAsThePwm) {
  // crazyflie_pid mixes on the 16-bit scale; at rest on its reference, level, its thrust is
  // THRUST_BASE 30000 on every motor. The fork's powerDistributionLegacy hands that to the motors
  // unchanged (no thrustToPWM): duty 30000 / 65535 = 0.457771.
  QuadrotorParams q = brushlessMotor();
  q.mass = 0.037;
  q.gravity = 9.81;
  q.max_thrust = 3.86e-8 * 2590.0 * 2590.0;
  q.rotor_xy = QuadrotorParams::xLayout(0.05);
  q.torque_per_thrust = 0.00569278844371417;
  CrazyfliePidController pid(q, CrazyfliePidGains{});
  CrazyflieThrustPath path;
  path.map = CrazyflieThrustMap::PwmQuadratic;
  pid.setThrustPath(path);
  pid.reset();
  VehicleState s;
  s.position = {0, 0, 1};
  s.battery_voltage = 3.9;
  FlatReference ref;
  ref.position = {0, 0, 1};
  const ControlOutput out = pid.update(s, ref, 0.002);
  ASSERT_TRUE(out.drives_duty);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(out.motor_duty[i], 30000.0 / 65535.0, 1e-9) << i;
}

}  // namespace
}  // namespace cosim
