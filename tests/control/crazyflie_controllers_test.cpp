// The crazyflie-firmware controllers (crazyflie_lee, crazyflie_mellinger, crazyflie_pid) against
// cases worked by hand from their papers with the firmware's default gains, their loop rates,
// limits, and a closed-loop hover on the Brushless airframe.
#include <gtest/gtest.h>

#include <cmath>

#include "control/controller_factory.h"
#include "control/crazyflie_lee_controller.h"
#include "control/crazyflie_mellinger_controller.h"
#include "control/crazyflie_pid_controller.h"
#include "tests/control/rigid_body_quadrotor.h"

namespace cosim {
namespace {

// models/cf21_brushless.xml as a controller sees it, at the flown 37 g.
QuadrotorParams brushless(double mass = 0.037) {
  QuadrotorParams q;
  q.mass = mass;
  q.inertia = Eigen::Vector3d(2.3205e-5, 2.3322e-5, 4.0974e-5) * (mass / 0.032);
  q.rotor_xy = QuadrotorParams::xLayout(0.050);
  q.torque_per_thrust = 0.00569278844371417;
  q.thrust_coefficient = 3.86e-8;
  q.max_rotor_speed = 2590.0;
  q.max_thrust = 3.86e-8 * 2590.0 * 2590.0;
  q.time_constant_up = 0.015;
  q.time_constant_down = 0.03;
  return q;
}

VehicleState levelAt(const Eigen::Vector3d& p) {
  VehicleState s;
  s.position = p;
  return s;
}

FlatReference at(const Eigen::Vector3d& p) {
  FlatReference r;
  r.position = p;
  return r;
}

TEST(CrazyflieLee, PositionErrorTiltsTheThrustAsLeeEquationFifteen) {
  // Level hover at the origin, set-point 0.1 m ahead in x. Lee et al. eq. 15 (z up) with the
  // firmware's Kpos_P = 7, Kpos_D = 4 and the believed mass m of the given 37 g airframe:
  //   F_d = K_x e_x + g e3 = (0.7, 0, 9.81) m/s^2; T = m F_d . e3 = 0.037 x 9.81 = 0.36297 N.
  //   b3d = F_d / |F_d| = (0.071175, 0, 0.997464): a 4.0815 deg tilt towards +x;
  //   e_R = vee(R_d^T - R_d) / 2 = (0, -0.071175, 0);
  //   M_y = -KR_y e_R,y - KI_y (dt e_R,y) = (0.007 + 0.03 x 0.002) x 0.0711748
  //       = 0.00706 x 0.0711748 = 5.02494e-4 N m.
  CrazyflieLeeController lee(brushless());
  lee.reset();
  const auto c = lee.law(levelAt({0, 0, 0}), at({0.1, 0, 0}));
  EXPECT_NEAR(c.thrust, 0.36297, 1e-9);
  EXPECT_NEAR(c.R_d(0, 2), 0.071175, 1e-6);
  EXPECT_NEAR(c.R_d(2, 2), 0.997464, 1e-6);
  EXPECT_NEAR(c.torque.y(), 5.02494e-4, 1e-9);
  EXPECT_NEAR(c.torque.x(), 0.0, 1e-12);
  EXPECT_NEAR(c.torque.z(), 0.0, 1e-12);
}

TEST(CrazyflieLee, JerkFeedForwardGivesTheDesiredBodyRate) {
  // No error, reference jerk (1, 0, 0) m/s^3: h_w = m / T (j - (b3d . j) b3d) = j / g, so the
  // desired pitch rate is 1 / 9.81 = 0.101937 rad/s and M_y = Komega_y 0.101937 = 1.17228e-4 N m.
  CrazyflieLeeController lee(brushless());
  lee.reset();
  FlatReference r = at({0, 0, 1});
  r.jerk = {1.0, 0.0, 0.0};
  const auto c = lee.law(levelAt({0, 0, 1}), r);
  EXPECT_NEAR(c.torque.y(), 0.00115 / 9.81, 1e-10);
}

TEST(CrazyflieLee, ErrorsAreClampedToTheFirmwareLimits) {
  // Kpos_P_limit = 100 m: a 250 m error counts as 100 m, F_d,x = 700 m/s^2.
  CrazyflieLeeController lee(brushless());
  lee.reset();
  const auto c = lee.law(levelAt({0, 0, 0}), at({250, 0, 0}));
  EXPECT_NEAR(c.R_d(0, 2), 700.0 / std::hypot(700.0, 9.81), 1e-9);
}

TEST(CrazyflieLee, BelievesTheGivenAirframesMassUnlessTheMassGainIsSet) {
  // No error, level hover: T = m g. Without ctrlLee.mass, m is the given airframe's 37 g
  // (T = 0.037 x 9.81 = 0.36297 N); with mass: 0.0393 (the firmware's unconfigured CF_MASS),
  // T = 0.0393 x 9.81 = 0.385533 N.
  CrazyflieLeeController configured(brushless());
  configured.reset();
  EXPECT_NEAR(configured.law(levelAt({0, 0, 1}), at({0, 0, 1})).thrust, 0.037 * 9.81, 1e-9);
  CrazyflieLeeGains firmware_default;
  firmware_default.mass = 0.0393;
  CrazyflieLeeController unconfigured(brushless(), firmware_default);
  unconfigured.reset();
  EXPECT_NEAR(unconfigured.law(levelAt({0, 0, 1}), at({0, 0, 1})).thrust, 0.0393 * 9.81, 1e-9);
}

// The height at which crazyflie_lee settles in 6 s of hover at 1 m on the 37 g airframe.
double leeHoverHeight(const CrazyflieLeeGains& gains) {
  const QuadrotorParams q = brushless();
  CrazyflieLeeController lee(q, gains);
  lee.reset();
  testing::RigidBodyQuadrotor plant(q);
  plant.state.position = {0, 0, 1};
  ControlOutput u;
  for (int i = 0; i < 6000; ++i) {  // 6 s at 1 kHz, the controller at 500 Hz
    if (i % 2 == 0) u = lee.update(plant.measured(), at({0, 0, 1}), 0.002);
    plant.step(u.rotor_thrusts, 0.001);
  }
  EXPECT_NEAR(plant.state.position.x(), 0.0, 1e-6);
  return plant.state.position.z();
}

TEST(CrazyflieLee, HoversHighByTheMassAnUnconfiguredFirmwareDoesNotKnowAbout) {
  // Firmware left at CF_MASS = 39.3 g on the 37 g vehicle, Kpos_I = 0. In steady hover
  // 0.0393 (9.81 + 7 e_z) = 0.037 x 9.81, so e_z = (0.037 / 0.0393 - 1) 9.81 / 7 = -0.08202 m:
  // it settles 8.2 cm above its set-point.
  CrazyflieLeeGains firmware_default;
  firmware_default.mass = 0.0393;
  EXPECT_NEAR(leeHoverHeight(firmware_default) - 1.0, 0.08202, 2e-3);
  // Configured (believing the airframe's 37 g): the weight is met at e_z = 0, no offset.
  EXPECT_LT(std::abs(leeHoverHeight({}) - 1.0), 0.01);
}

TEST(CrazyflieMellinger, DesiredThrustAndRotationErrorAsMellingerAndKumar) {
  // Level hover, set-point 0.1 m ahead in x, firmware gains (kp_xy 0.4 N/m, ki_xy 0.05 N/(m s))
  // and the given airframe's mass 0.037 kg: F_des = (0.4 x 0.1 + 0.05 x 0.1 x 0.002, 0,
  // 0.037 x 9.81) = (0.04001, 0, 0.36297) N; thrust = massThrust F_des . z_B = 132000 x 0.36297
  // = 47912.04; |F_des| = sqrt(0.04001^2 + 0.36297^2) = 0.365168, and e_R = vee(R_des^T - R_des)
  // (no 1/2) has e_R,y = -2 x 0.04001 / 0.365168 = -0.219132, so M_y = -kR_xy e_R,y
  // = 70000 x 0.219132 = 15339.2 (kd_omega_rp acts from the second step).
  CrazyflieMellingerController mel(brushless());
  mel.reset();
  const auto c = mel.law(levelAt({0, 0, 0}), at({0.1, 0, 0}));
  EXPECT_NEAR(c.force.x(), 0.04001, 1e-9);
  EXPECT_NEAR(c.thrust_pwm, 47912.04, 1e-2);
  EXPECT_NEAR(c.e_R.y(), -0.219132, 1e-6);
  EXPECT_NEAR(c.moment.y(), 15339.22, 1e-1);
}

TEST(CrazyflieMellinger, PositionIntegralStopsAtItsRange) {
  // i_range_z = 0.4 m s: a 1 m height error held for 2 s (0.5 s of it reaches the range) adds
  // at most ki_z 0.4 = 0.02 N on top of m g + kp_z e_z, with ctrlMel.mass set to the firmware's
  // CF_MASS 0.0393 kg (the 37 g airframe would otherwise be believed).
  CrazyflieMellingerGains gains;
  gains.mass = 0.0393;
  CrazyflieMellingerController mel(brushless(), gains);
  mel.reset();
  CrazyflieMellingerController::Command c;
  for (int i = 0; i < 1000; ++i) c = mel.law(levelAt({0, 0, 0}), at({0, 0, 1}));
  EXPECT_NEAR(c.force.z(), 0.0393 * 9.81 + 1.25 * 1.0 + 0.05 * 0.4, 1e-9);
}

TEST(CrazyfliePid, OneStepOfTheCascadeWithTheFirmwareGains) {
  // Level hover, set-point 0.1 m ahead in x, first tick (position and attitude both run):
  //   position P: v_sp = 2 x 0.1 = 0.2 m/s;
  //   velocity PI: pitch_d = 25 x 0.2 + 1 x (0.2 x 0.01) = 5.002 deg (right-handed, nose down);
  //   thrust = 1000 x 0 + THRUST_BASE 30000;
  //   attitude PI: rate_d = 6 x 5.002 + 3 x (5.002 x 0.002) = 30.042012 deg/s;
  //   rate PID: 200 x 30.042012 + 400 x (30.042012 x 0.002) + 2.5 x 0 = 6008.4024 + 24.0336096
  //   = 6032.4360096.
  CrazyfliePidController pid(brushless());
  pid.reset();
  pid.update(levelAt({0, 0, 1}), at({0.1, 0, 1}), 0.002);
  EXPECT_NEAR(pid.positionOutput().velocity_setpoint.x(), 0.2, 1e-12);
  EXPECT_NEAR(pid.positionOutput().pitch_deg, 5.002, 1e-9);
  EXPECT_NEAR(pid.positionOutput().thrust, 30000.0, 1e-9);
  EXPECT_NEAR(pid.attitudeOutput().y(), 6032.4360096, 1e-6);
  EXPECT_NEAR(pid.attitudeOutput().x(), 0.0, 1e-12);
}

TEST(CrazyfliePid, PositionLoopRunsAtOneHundredHertzInsideTheFiveHundredHertzLoop) {
  // Called at 500 Hz with a velocity that changes every call: the velocity loop's pitch changes
  // only on every fifth call (POSITION_RATE), the rate loop's output on every call.
  CrazyfliePidController pid(brushless());
  pid.reset();
  double last_pitch = 0.0, last_rate = 0.0;
  int pitch_changes = 0, rate_changes = 0;
  for (int i = 0; i < 25; ++i) {
    VehicleState s = levelAt({0, 0, 1});
    s.velocity.x() = 0.01 * i;
    pid.update(s, at({0.1, 0, 1}), 0.002);
    pitch_changes += pid.positionOutput().pitch_deg != last_pitch;
    rate_changes += pid.attitudeOutput().y() != last_rate;
    last_pitch = pid.positionOutput().pitch_deg;
    last_rate = pid.attitudeOutput().y();
  }
  EXPECT_EQ(pitch_changes, 5);
  EXPECT_EQ(rate_changes, 25);
}

TEST(CrazyfliePid, VelocityAndTiltLimitsHoldAsTheFirmwareDefaults) {
  // A 5 m error: the velocity set-point stops at PID_POS_VEL_X_MAX x 1.10 = 1.1 m/s, and the
  // pitch at PID_VEL_PITCH_MAX = 20 deg (25 x 1.1 = 27.5 deg before the limit).
  CrazyfliePidController pid(brushless());
  pid.reset();
  pid.update(levelAt({0, 0, 1}), at({5, 0, 1}), 0.002);
  EXPECT_NEAR(pid.positionOutput().velocity_setpoint.x(), 1.1, 1e-12);
  EXPECT_NEAR(pid.positionOutput().pitch_deg, 20.0, 1e-12);
}

TEST(CrazyflieControllers, FactoryBuildsThemWithGainsAndRejectsMisspeltOnes) {
  ParamSet gains("test.yaml");
  gains.set("kpos_p_xy", "9");
  auto c = makeFlightController("crazyflie_lee", gains, brushless());
  EXPECT_EQ(c->name(), "crazyflie_lee");
  ParamSet bad("test.yaml");
  bad.set("kpos_p", "9");
  EXPECT_THROW(makeFlightController("crazyflie_lee", bad, brushless()), std::exception);
  ParamSet none("test.yaml");
  EXPECT_EQ(makeFlightController("crazyflie_pid", none, brushless())->name(), "crazyflie_pid");
  EXPECT_EQ(makeFlightController("crazyflie_mellinger", none, brushless())->name(),
            "crazyflie_mellinger");
}

}  // namespace
}  // namespace cosim
