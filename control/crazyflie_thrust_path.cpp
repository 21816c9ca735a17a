#include "control/crazyflie_thrust_path.h"

#include <algorithm>

namespace cosim {

namespace {
constexpr double kGramsPerNewton = 1000.0 / 9.81;  // thrustToPWM: motorForce * 1000.0f / 9.81f
}  // namespace

double CrazyflieThrustPath::idleThrust() const {
  if (idle_thrust) return *idle_thrust;
  return map == CrazyflieThrustMap::PwmQuadratic ? kImrcForkIdleThrust : 0.0;
}

std::optional<CrazyflieThrustMap> crazyflieThrustMapNamed(const std::string& name) {
  if (name == "battery_compensated") return CrazyflieThrustMap::BatteryCompensated;
  if (name == "pwm_quadratic") return CrazyflieThrustMap::PwmQuadratic;
  return std::nullopt;
}

std::optional<CrazyflieMixerPlatform> crazyflieMixerPlatformNamed(const std::string& name) {
  if (name == "cf21bl") return CrazyflieMixerPlatform::Cf21bl;
  if (name == "cf2") return CrazyflieMixerPlatform::Cf2;
  return std::nullopt;
}

CrazyfliePlatform crazyflieMixerConstants(const CrazyfliePlatform& build,
                                          CrazyflieMixerPlatform platform) {
  CrazyfliePlatform p = build;
  if (platform == CrazyflieMixerPlatform::Cf2) {
    p.arm_length = 0.046;  // platform_defaults_cf2.h ARM_LENGTH (the fork and upstream agree)
    // The fork's power_distribution_quadrotor.c: static float thrustToTorque = 0.005964552f
    // (parameter quadSysId.thrustToTorque; Foerster 2015's load-cell fit for the cf2). Upstream's
    // platform_defaults_cf2.h now sets per-propeller THRUST2TORQUE values instead; the fork's is
    // the one the rig flew.
    p.thrust_to_torque = 0.005964552;
  }
  return p;
}

double pwmQuadraticDuty(const Eigen::Vector3d& d, double force) {
  if (!(force > 0.0)) return 0.0;
  const double g = force * kGramsPerNewton;
  return d[0] + g * (d[1] + g * d[2]);
}

Eigen::Vector4d capCrazyflieDuties(const Eigen::Vector4d& duty, double idle_duty, bool* capped) {
  const double excess = std::max(duty.maxCoeff() - 1.0, 0.0);
  if (capped) *capped = excess > 0.0;
  return (duty.array() - excess).max(idle_duty).matrix();
}

Eigen::Vector4d crazyflieMotorDuties(const CrazyflieThrustPath& path, const CrazyflieMotors& motors,
                                     const Eigen::Vector4d& forces, double battery_voltage,
                                     bool* capped) {
  Eigen::Vector4d duty;
  for (int i = 0; i < 4; ++i) {
    if (path.map == CrazyflieThrustMap::PwmQuadratic) {
      duty[i] = pwmQuadraticDuty(path.pwm_quadratic, forces[i]);
      continue;
    }
    // motorsCompensateBatteryVoltage: 0 below 2 V (a damaged battery) and below THRUST_MIN.
    const bool off = battery_voltage < 2.0 || forces[i] < motors.platform().thrust_min;
    duty[i] = off ? 0.0 : motors.voltageForThrust(forces[i]) / battery_voltage;
  }
  return capCrazyflieDuties(duty, path.idleThrust() / 65535.0, capped);
}

}  // namespace cosim
