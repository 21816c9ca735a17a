#pragma once
// How a crazyflie-firmware build turns per-motor forces into motor PWM, per build:
//  - `battery_compensated` (upstream crazyflie-firmware for the Crazyflie 2.1 Brushless,
//    CONFIG_ENABLE_THRUST_BAT_COMPENSATED, on by default): each force becomes the motor voltage
//    of the platform's thrust curve VMOTOR2THRUST0..3, and the duty cycle is that voltage over the
//    measured battery voltage (motors.c, motorsCompensateBatteryVoltage: ratio = motorVoltage /
//    supplyVoltage), so the thrust does not drift as the battery sags;
//  - `pwm_quadratic` (IMRCLab's 2024 fork, dev-coltrans: power_distribution_quadrotor.c,
//    thrustToPWM): duty = d00 + d10 g + d01 v + d20 g^2 + d11 g v with g the motor's force in
//    grams (force 1000 / 9.81) and v the battery voltage / 4.2; the flights of
//    crazyflie-data-collection's brushless_flights set d01 = d11 = 0 (its README's
//    firmware_params), and configs/cfbl_defconfig sets CONFIG_ENABLE_THRUST_BAT_COMPENSATED=n:
//    the PWM does not depend on the battery at all, and the thrust follows its voltage.
// Both then cap (power_distribution_quadrotor.c, powerDistributionCap): if the highest PWM passes
// 65535 every motor drops by the excess, and no motor goes below powerDist.idleThrust.
#include <Eigen/Core>
#include <optional>
#include <string>

#include "control/crazyflie_platform.h"

namespace cosim {

enum class CrazyflieThrustMap { BatteryCompensated, PwmQuadratic };

// What the power distribution assumes of the airframe: the build's own platform, or the
// Crazyflie 2's (which IMRCLab's 2024 fork used on the Brushless: its cfbl_defconfig selects no
// platform, so Kconfig's default CONFIG_PLATFORM_CF2 applies).
enum class CrazyflieMixerPlatform { Cf21bl, Cf2 };

// IMRCLab crazyflie-data-collection brushless_flights/README.md, firmware_params pwm: d00, d10,
// d20 (d01 = d11 = 0): normalised PWM from grams per motor.
inline const Eigen::Vector3d kImrcForkPwmQuadratic{0.16609668469985447, 0.02297914810965436,
                                                   0.0001878280261464696};
// IMRCLab crazyflie-firmware (dev-coltrans, 2024-05-29 "switch to old power distribution")
// configs/cfbl_defconfig: CONFIG_MOTORS_DEFAULT_IDLE_THRUST=10000.
constexpr double kImrcForkIdleThrust = 10000.0;

// The controller keys `thrust_map`, `thrust_map_coefficients`, `idle_thrust` and `platform`.
struct CrazyflieThrustPath {
  CrazyflieThrustMap map = CrazyflieThrustMap::BatteryCompensated;
  Eigen::Vector3d pwm_quadratic = kImrcForkPwmQuadratic;  // d00, d10 (1/g), d20 (1/g^2)
  // powerDist.idleThrust, PWM (0..65535); unset: the build's default, 0 for battery_compensated
  // (cosim's Brushless behaviour so far, every rotor may stop) and 10000 for pwm_quadratic.
  std::optional<double> idle_thrust;
  CrazyflieMixerPlatform platform = CrazyflieMixerPlatform::Cf21bl;

  double idleThrust() const;
  // pwm_quadratic leaves the thrust to the battery's voltage, so it flies only on a simulated
  // battery; battery_compensated flies on one when the vehicle carries it, else on an ideal supply.
  bool needsBattery() const { return map == CrazyflieThrustMap::PwmQuadratic; }
};

// The names the scenario uses ("battery_compensated", "pwm_quadratic"; "cf21bl", "cf2").
std::optional<CrazyflieThrustMap> crazyflieThrustMapNamed(const std::string& name);
std::optional<CrazyflieMixerPlatform> crazyflieMixerPlatformNamed(const std::string& name);

// The platform whose power distribution runs: the build's own, or with the Crazyflie 2's arm
// length and thrust-to-torque ratio.
CrazyfliePlatform crazyflieMixerConstants(const CrazyfliePlatform& build,
                                          CrazyflieMixerPlatform platform);

// pwm_quadratic's normalised PWM for a motor force (N): 0 for no force (thrustToPWM returns 0
// unless thrustGram > 0), else d00 + d10 g + d20 g^2, g in grams.
double pwmQuadraticDuty(const Eigen::Vector3d& d, double force);

// powerDistributionCap on duty cycles (PWM / 65535): if the highest exceeds 1, every one drops by
// the excess; none goes below idle_duty. *capped says whether the top was cut.
Eigen::Vector4d capCrazyflieDuties(const Eigen::Vector4d& duty, double idle_duty, bool* capped);

// The whole duty-cycle path for per-motor forces (N, firmware order) and the measured battery
// voltage (V): battery_compensated through `motors` (VMOTOR2THRUST), pwm_quadratic through the
// fork's map; then capped.
Eigen::Vector4d crazyflieMotorDuties(const CrazyflieThrustPath& path, const CrazyflieMotors& motors,
                                     const Eigen::Vector4d& forces, double battery_voltage,
                                     bool* capped);

}  // namespace cosim
