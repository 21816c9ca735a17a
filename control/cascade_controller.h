#pragma once
// The cascade of seed 003 (its Fig. 2, after Quan 2017, "Introduction to Multicopter Design and
// Control"): position -> velocity -> (collective thrust, desired roll/pitch/yaw) -> attitude ->
// body rates -> body torques -> mixer -> four rotor thrusts.
#include "control/flight_controller.h"
#include "control/mixer.h"
#include "control/pid.h"

namespace cosim {

struct CascadeGains {
  double pos_kp = 1.0;                       // 1/s: position error -> velocity command
  double vel_kp = 3.0;                       // 1/s: velocity error -> acceleration command
  double vel_ki = 1.0;                       // 1/s^2
  double vel_i_limit = 3.0;                  // m/s^2, bound on the integral's contribution
  double max_speed_xy = 3.0;                 // m/s, horizontal velocity command limit
  double max_speed_z = 1.5;                  // m/s
  double max_tilt_deg = 35.0;                // limit on the thrust vector's angle from vertical
  Eigen::Vector3d att_kp{7.0, 7.0, 3.0};     // 1/s: attitude error -> body rate command
  Eigen::Vector3d rate_kp{18.0, 18.0, 8.0};  // 1/s: rate error -> angular acceleration
  Eigen::Vector3d rate_ki{4.0, 4.0, 1.0};
  Eigen::Vector3d rate_i_limit{20.0, 20.0, 5.0};  // rad/s^2
  double max_rate = 6.0;                          // rad/s, roll/pitch rate command limit
};

class CascadeController : public FlightController {
 public:
  CascadeController(const QuadrotorParams& params, const CascadeGains& gains);
  static constexpr char kName[] = "cascade";
  std::string name() const override { return kName; }
  void reset() override;
  ControlOutput update(const VehicleState& state, const FlatReference& ref, double dt) override;

  // The attitude set-point of the last update (roll, pitch, yaw in rad), for logging.
  const Eigen::Vector3d& desiredRollPitchYaw() const { return desired_rpy_; }

 private:
  QuadrotorParams params_;
  CascadeGains gains_;
  Mixer mixer_;
  Pid vel_pid_[3];
  Pid rate_pid_[3];
  int accel_saturated_[3] = {0, 0, 0};
  int rate_saturated_[3] = {0, 0, 0};
  Eigen::Vector3d desired_rpy_ = Eigen::Vector3d::Zero();
};

class ControllerRegistry;
// Registers cascade (its gains, team margin, ...) in the controller registry.
void registerCascadeController(ControllerRegistry& registry);

}  // namespace cosim
