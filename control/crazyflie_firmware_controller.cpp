#include "control/crazyflie_firmware_controller.h"

#include <cmath>

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
    : platform_(platform), motors_(platform, airframe.max_thrust), mixer_(airframe) {}

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
  const Eigen::Vector4d forces = lawStep(state, setpoint_, clock_);
  bool capped = false;
  output_.rotor_thrusts = crazyflieToRotorOrder(motors_.deliver(forces, &capped));
  const Eigen::Vector4d wrench = mixer_.wrench(output_.rotor_thrusts);
  output_.collective_thrust = wrench[0];
  output_.torque = wrench.tail<3>();
  output_.saturated = capped;
  return output_;
}

}  // namespace cosim
