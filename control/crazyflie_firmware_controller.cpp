#include "control/crazyflie_firmware_controller.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cosim {

Eigen::Vector3d highLevelCommanderRates(const FlatReference& ref, double gravity) {
  const Eigen::Vector3d thrust = ref.acceleration + gravity * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d z = thrust.normalized();
  const Eigen::Vector3d x_world(std::cos(ref.yaw), std::sin(ref.yaw), 0.0);
  const Eigen::Vector3d y = z.cross(x_world).normalized();
  const Eigen::Vector3d x = y.cross(z);
  const Eigen::Vector3d h = (ref.jerk - ref.jerk.dot(z) * z) / thrust.norm();
  return {-h.dot(y), h.dot(x), z.z() * ref.yaw_rate};
}

CrazyflieFirmwareController::CrazyflieFirmwareController(const QuadrotorParams& airframe,
                                                         const CrazyfliePlatform& platform)
    : platform_(platform),
      build_platform_(platform),
      motors_(platform, airframe.max_thrust),
      mixer_(airframe) {}

void CrazyflieFirmwareController::reset() {
  clock_.reset();
  setpoint_ = FlatReference{};
  output_ = ControlOutput{};
  resetLaw();
}

ControlOutput CrazyflieFirmwareController::update(const VehicleState& state,
                                                  const FlatReference& ref, double dt) {
  clock_.advance(dt);
  // The high-level commander (crtp_commander_high_level.c) evaluates the trajectory at
  // RATE_HL_COMMANDER = 100 Hz; the stabilizer reads its latest setpoint.
  if (clock_.due(100.0)) setpoint_ = ref;
  if (!clock_.due(kCrazyflieAttitudeRate)) return output_;
  deliver(lawStep(state, setpoint_, clock_), state.battery_voltage);
  return output_;
}

void CrazyflieFirmwareController::setThrustPath(const CrazyflieThrustPath& path) {
  path_ = path;
  platform_ = crazyflieMixerConstants(build_platform_, path.platform);
  // Without a battery the idle PWM's duty makes the thrust of that fraction of full-scale volts
  // (the supply at which full duty is the rotors' maximum, crazyflie_platform.h).
  const double idle_volts = path.idleThrust() / 65535.0 * motors_.fullScaleVolts();
  idle_force_ = path.idleThrust() > 0.0 && std::isfinite(idle_volts)
                    ? std::max(motors_.thrustAtVoltage(idle_volts), 0.0)
                    : 0.0;
}

Eigen::Vector4d CrazyflieFirmwareController::motorDuties(const Eigen::Vector4d& forces,
                                                         double battery_voltage,
                                                         bool* capped) const {
  if (path_.map != CrazyflieThrustMap::PwmQuadratic || !legacyMode())
    return crazyflieMotorDuties(path_, motors_, forces, battery_voltage, capped);
  // The fork's powerDistributionLegacy has no thrustToPWM: the legacy mix's 16-bit values
  // (u, read here as u / 65535 THRUST_MAX newtons) are the PWM as they are.
  const Eigen::Vector4d duty = forces.cwiseMax(0.0) / platform_.thrust_max;
  return capCrazyflieDuties(duty, path_.idleThrust() / 65535.0, capped);
}

void CrazyflieFirmwareController::deliver(const Eigen::Vector4d& forces, double battery_voltage) {
  bool capped = false;
  if (battery_voltage > 0.0) {
    // The firmware's PWM goes to the motors as duty cycles; the thrust they make is the
    // simulated motors' business. rotor_thrusts keeps the forces the law asked for (the log).
    output_.motor_duty = crazyflieToRotorOrder(motorDuties(forces, battery_voltage, &capped));
    output_.drives_duty = true;
    output_.rotor_thrusts = crazyflieToRotorOrder(forces.cwiseMax(0.0));
  } else if (path_.needsBattery()) {
    throw std::logic_error("crazyflie thrust map pwm_quadratic flown without a battery");
  } else {
    output_.rotor_thrusts =
        crazyflieToRotorOrder(motors_.deliver(forces, &capped).cwiseMax(idle_force_));
  }
  const Eigen::Vector4d wrench = mixer_.wrench(output_.rotor_thrusts);
  output_.collective_thrust = wrench[0];
  output_.torque = wrench.tail<3>();
  output_.saturated = capped;
}

}  // namespace cosim
