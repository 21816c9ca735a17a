#include "control/crazyflie_platform.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cosim {

namespace {
constexpr double kPwmFullScale = 65535.0;  // UINT16_MAX: the firmware's 16-bit thrust and PWM scale

// The thrust curve's inverse (voltageForThrust) relies on a curve rising and convex for v >= 0.
const CrazyfliePlatform& withRisingConvexCurve(const CrazyfliePlatform& p) {
  const Eigen::Vector4d& c = p.vmotor2thrust;
  if (!(c[1] > 0.0 && c[2] >= 0.0 && c[3] > 0.0))
    throw std::invalid_argument(
        "CrazyflieMotors: VMOTOR2THRUST1 and 3 must be positive, 2 non-negative");
  return p;
}
}  // namespace

CrazyfliePlatform crazyflie21BrushlessPlatform() {
  CrazyfliePlatform p;
  // crazyflie-firmware src/platform/interface/platform_defaults_cf21bl.h (2025-10 onwards, with
  // CONFIG_ENABLE_THRUST_BAT_COMPENSATED, which Kconfig enables by default for CF21BL):
  p.mass = 0.0393;                           // CF_MASS (guards, 350 mAh battery, LH deck)
  p.arm_length = 0.050;                      // ARM_LENGTH
  p.thrust_to_torque = 0.00569278844371417;  // THRUST2TORQUE
  p.thrust_max = 0.2;                  // THRUST_MAX (THRUST_BAT_COMPENSATION_MAX_THRUST 200 mN)
  p.thrust_min = 0.02136263065537499;  // THRUST_MIN
  p.vmotor2thrust = {-0.014058926705279723,   // VMOTOR2THRUST0
                     0.04265273261724981,     // VMOTOR2THRUST1
                     0.0018327760144017432,   // VMOTOR2THRUST2
                     0.0020576974784587178};  // VMOTOR2THRUST3
  p.gravity = 9.81;  // src/utils/interface/physicalConstants.h GRAVITY_MAGNITUDE
  return p;
}

CrazyflieMotors::CrazyflieMotors(const CrazyfliePlatform& platform, double max_rotor_thrust)
    : p_(withRisingConvexCurve(platform)) {
  // The roots at thrusts c0 + i step, up to the curve's thrust at 5 V (0.50 N, past the
  // Brushless's full scale, 3.6 V), each found from the cbrt start.
  const Eigen::Vector4d& c = p_.vmotor2thrust;
  table_step_ = (thrustAtVoltage(5.0) - c[0]) / (kTableSize - 1);
  for (int i = 0; i < kTableSize; ++i) {
    const double thrust = c[0] + i * table_step_;
    table_[i] = i == 0 ? 0.0 : newtonFrom(std::cbrt((thrust - c[0]) / c[3]), thrust);
  }
  full_scale_volts_ = std::isfinite(max_rotor_thrust) ? voltageForThrust(max_rotor_thrust)
                                                      : std::numeric_limits<double>::infinity();
  full_scale_thrust_ = max_rotor_thrust;
}

double CrazyflieMotors::thrustAtVoltage(double v) const {
  const Eigen::Vector4d& c = p_.vmotor2thrust;
  return c[0] + v * (c[1] + v * (c[2] + v * c[3]));
}

double CrazyflieMotors::newtonFrom(double v, double thrust) const {
  // The cubic f rises and is convex for v >= 0 (c1, c3 > 0, c2 >= 0: f' > 0 and f'' = 2 c2 +
  // 6 c3 v > 0), so a Newton step from anywhere lands at or above the root (the tangent lies
  // under f) and from there Newton falls monotonically onto it: after the first step it stops
  // when a step no longer lowers v, the root to the last bit.
  const Eigen::Vector4d& c = p_.vmotor2thrust;
  for (int i = 0; i < 100; ++i) {
    const double slope = c[1] + v * (2.0 * c[2] + v * 3.0 * c[3]);
    const double next = v - (thrustAtVoltage(v) - thrust) / slope;
    if (i > 0 && !(next < v)) break;
    v = next;
  }
  return v;
}

double CrazyflieMotors::voltageForThrust(double thrust) const {
  const Eigen::Vector4d& c = p_.vmotor2thrust;
  if (!(thrust > c[0])) return 0.0;  // at or below the curve's value at 0 V: the motor is off
  // Start: the chord of the inverse between two tabulated roots (within 6e-5 V; the inverse is
  // concave, so the chord lies below it), or beyond the table v0 = cbrt((T - c0) / c3), where
  // the cubic term alone makes T (f(v0) >= T). About three steps from the chord, six from v0;
  // this runs four times a control step.
  const double k = (thrust - c[0]) / table_step_;
  if (k < static_cast<double>(kTableSize - 1)) {
    const int i = static_cast<int>(k);
    const double v0 = table_[i] + (k - i) * (table_[i + 1] - table_[i]);
    return newtonFrom(v0, thrust);
  }
  return newtonFrom(std::cbrt((thrust - c[0]) / c[3]), thrust);
}

Eigen::Vector4d CrazyflieMotors::deliver(const Eigen::Vector4d& requested, bool* capped) const {
  // Battery compensation (motors.c): the motor voltage for each force; off below THRUST_MIN (and
  // at or below the curve's thrust at 0 V). The duty cycle is that voltage over the supply, so an
  // equal duty reduction is an equal voltage reduction, and full duty is full_scale_volts_.
  const Eigen::Vector4d& c = p_.vmotor2thrust;
  Eigen::Vector4d thrust;
  double strongest = 0.0;
  for (int i = 0; i < 4; ++i) {
    const bool off = requested[i] < p_.thrust_min || !(requested[i] > c[0]);
    thrust[i] = off ? 0.0 : std::max(requested[i], 0.0);
    if (!off) strongest = std::max(strongest, requested[i]);
  }
  // Uncapped, each motor makes what was asked of it (voltage then thrust is the identity), so
  // the voltages are solved for only when the strongest request passes full scale (the curve
  // rises: the strongest thrust has the highest voltage). This runs at every control step.
  const bool cap = strongest > full_scale_thrust_;
  if (capped) *capped = cap;
  if (!cap) return thrust;
  // Capping (power_distribution_quadrotor.c, powerDistributionCap): every motor drops by the
  // highest one's excess over full scale, and none goes below zero (the idle thrust, 0).
  Eigen::Vector4d volts;
  for (int i = 0; i < 4; ++i) volts[i] = thrust[i] == 0.0 ? 0.0 : voltageForThrust(requested[i]);
  const double excess = volts.maxCoeff() - full_scale_volts_;
  for (int i = 0; i < 4; ++i) {
    const double v = std::max(volts[i] - excess, 0.0);
    thrust[i] = v > 0.0 ? std::max(thrustAtVoltage(v), 0.0) : 0.0;
  }
  return thrust;
}

Eigen::Vector4d crazyflieForceTorqueMix(const CrazyfliePlatform& p, double thrust,
                                        const Eigen::Vector3d& torque) {
  // power_distribution_quadrotor.c, powerDistributionForceTorque: each motor's lever about x and
  // y is ARM_LENGTH / sqrt(2) (X layout); yaw through THRUST2TORQUE. M1 front right and M3 back
  // left turn counter-clockwise (reaction torque -z), M2 and M4 clockwise.
  const double lever = p.arm_length / std::sqrt(2.0);
  const double t = 0.25 * thrust;
  const double r = 0.25 * torque.x() / lever;
  const double q = 0.25 * torque.y() / lever;
  const double y = 0.25 * torque.z() / p.thrust_to_torque;
  Eigen::Vector4d f(t - r - q - y, t - r + q + y, t + r + q - y, t + r - q + y);
  return f.cwiseMax(0.0);
}

Eigen::Vector4d crazyflieLegacyMix(const CrazyfliePlatform& p, double thrust, double roll,
                                   double pitch, double yaw) {
  // power_distribution_quadrotor.c, powerDistributionLegacy: half the roll and pitch commands
  // per motor (the firmware truncates them to integers, immaterial at this scale).
  const double r = roll / 2.0, q = pitch / 2.0;
  const Eigen::Vector4d u(thrust - r + q + yaw, thrust - r - q - yaw, thrust + r - q + yaw,
                          thrust + r + q - yaw);
  // Battery compensation reads the 16-bit value as u / 65535 THRUST_MAX newtons (motors.c).
  return (u / kPwmFullScale * p.thrust_max).cwiseMax(0.0);
}

Eigen::Vector4d crazyflieToRotorOrder(const Eigen::Vector4d& m) {
  // rotor0 front left = M4, rotor1 rear left = M3, rotor2 rear right = M2, rotor3 front right = M1.
  return {m[3], m[2], m[1], m[0]};
}

void CrazyflieClock::reset() {
  time_ = 0.0;
  started_ = false;
  previous_tick_ = -1;
  tick_ = 0;
}

void CrazyflieClock::advance(double dt) {
  if (!started_) {  // the first call after a reset is tick 0, when every part runs
    started_ = true;
    previous_tick_ = -1;
    tick_ = 0;
    return;
  }
  time_ += dt;
  previous_tick_ = tick_;
  tick_ = static_cast<long long>(std::floor(time_ * 1000.0 + 1e-6));  // RATE_MAIN_LOOP 1000 Hz
}

bool CrazyflieClock::due(double rate_hz) const {
  // RATE_DO_EXECUTE: tick % (1000 / rate) == 0 for some tick in (previous, current].
  const long long every = std::llround(1000.0 / rate_hz);
  const long long last_due = tick_ - ((tick_ % every) + every) % every;
  return last_due > previous_tick_;
}

}  // namespace cosim
