#pragma once
// crazyflie_pid: crazyflie-firmware's default cascaded PID controller (controller_pid.c with
// position_controller_pid.c and attitude_pid_controller.c), with the Crazyflie 2.1 Brushless
// build's default gains (platform_defaults_cf21bl.h), in its legacy control mode:
//   100 Hz (POSITION_RATE), in the yaw-rotated body frame:
//     v_sp   = PID_pos(x_d - x)              (m/s, each axis clamped to 1.1 = POS_VEL_MAX 1.10)
//                                              the reference velocity is NOT fed forward
//     pitch_d = PID_vx(v_sp,x - v_x), roll_d = -PID_vy(v_sp,y - v_y)   (deg, clamped to +-20)
//     thrust = 1000 PID_vz(v_sp,z - v_z) + THRUST_BASE, at least THRUST_MIN (16-bit scale)
//   500 Hz (ATTITUDE_RATE):
//     rate_d = PID_att(angle_d - angle)       (deg/s; yaw error wrapped to +-180)
//     u      = PID_rate(rate_d - gyro)        (16-bit scale, clamped to +-32767)
// Each PID is the firmware's pid.c: P on the error, D on the measurement's change (no kick), I
// clamped to its integration limit, output clamped to its output limit. Angles in degrees and
// right-handed (roll about x, pitch about y, positive nose down); the firmware's legacy pitch sign
// (positive nose up) is applied at the power distribution. The position and velocity loops' D
// gains are 0 by default, so their D low-pass filters (pid.c dFilter) do not act and are not
// modelled; the attitude loops' filters are off by default (ATTITUDE_LPF_ENABLE,
// ATTITUDE_RATE_LPF_ENABLE false).
#include "control/crazyflie_firmware_controller.h"

namespace cosim {

// pid.c's PidObject, as far as these loops use it.
struct CrazyfliePid {
  double kp = 0.0, ki = 0.0, kd = 0.0;
  double i_limit = 5000.0;    // DEFAULT_PID_INTEGRATION_LIMIT
  double output_limit = 0.0;  // 0: none (DEFAULT_PID_OUTPUT_LIMIT)
  double integ = 0.0, prev_measured = 0.0;
  void reset(double measured) {
    integ = 0.0;
    prev_measured = measured;
  }
  // One update over dt; `wrap_deg` wraps the error and the measurement's change to +-180.
  double update(double desired, double measured, double dt, bool wrap_deg = false);
};

// Defaults: platform_defaults_cf21bl.h (PID_*), position_controller_pid.c (limits, scales).
struct CrazyfliePidGains {
  double pos_kp_xy = 2.0, pos_ki_xy = 0.0;   // PID_POS_X_KP, PID_POS_X_KI (Y the same)
  double pos_kp_z = 2.0, pos_ki_z = 0.5;     // PID_POS_Z_KP, PID_POS_Z_KI
  double vel_kp_xy = 25.0, vel_ki_xy = 1.0;  // PID_VEL_X_KP, PID_VEL_X_KI, deg per m/s
  double vel_kp_z = 25.0, vel_ki_z = 15.0;   // PID_VEL_Z_KP, PID_VEL_Z_KI
  double vel_max = 1.0;                      // PID_POS_VEL_X/Y/Z_MAX, m/s (x 1.10 overhead)
  double rp_max_deg = 20.0;                  // PID_VEL_ROLL_MAX, PID_VEL_PITCH_MAX
  double thrust_base = 30000.0;              // PID_VEL_THRUST_BASE
  double thrust_min = 20000.0;               // PID_VEL_THRUST_MIN
  double att_kp_rp = 6.0, att_ki_rp = 3.0, att_i_limit_rp = 20.0;  // PID_ROLL_KP/KI/INT_LIMIT
  double att_kp_yaw = 6.0, att_ki_yaw = 1.0, att_kd_yaw = 0.35, att_i_limit_yaw = 360.0;
  double rate_kp_rp = 200.0, rate_ki_rp = 400.0, rate_kd_rp = 2.5, rate_i_limit_rp = 33.3;
  double rate_kp_yaw = 120.0, rate_ki_yaw = 16.7, rate_i_limit_yaw = 166.7;
};

class CrazyfliePidController : public CrazyflieFirmwareController {
 public:
  CrazyfliePidController(const QuadrotorParams& airframe, const CrazyfliePidGains& gains = {},
                         const CrazyfliePlatform& platform = crazyflie21BrushlessPlatform());
  static constexpr char kName[] = "crazyflie_pid";
  std::string name() const override { return kName; }

  // The 100 Hz part's outputs, held between its runs (exposed for tests).
  struct PositionOutput {
    Eigen::Vector3d velocity_setpoint = Eigen::Vector3d::Zero();  // body-yaw frame, m/s
    double roll_deg = 0.0, pitch_deg = 0.0;                       // right-handed
    double thrust = 0.0;                                          // 16-bit scale
  };
  const PositionOutput& positionOutput() const { return pos_; }
  // The last 500 Hz output: roll, pitch, yaw commands (right-handed, 16-bit scale).
  const Eigen::Vector3d& attitudeOutput() const { return att_out_; }

 protected:
  Eigen::Vector4d lawStep(const VehicleState& state, const FlatReference& setpoint,
                          const CrazyflieClock& clock) override;
  void resetLaw() override;
  bool legacyMode() const override { return true; }

 private:
  void positionStep(const VehicleState& s, const FlatReference& sp, double yaw_deg);
  void attitudeStep(const VehicleState& s, const Eigen::Vector3d& rpy_deg, double yaw_sp_deg);

  CrazyfliePidGains gains_;
  CrazyfliePid pid_x_, pid_y_, pid_z_, pid_vx_, pid_vy_, pid_vz_;
  CrazyfliePid pid_roll_, pid_pitch_, pid_yaw_, pid_roll_rate_, pid_pitch_rate_, pid_yaw_rate_;
  bool initialised_ = false;
  PositionOutput pos_;
  Eigen::Vector3d att_out_ = Eigen::Vector3d::Zero();
};

class ControllerRegistry;
// Registers crazyflie_pid (its gains, team margin, ...) in the controller registry.
void registerCrazyfliePidController(ControllerRegistry& registry);

}  // namespace cosim
