#pragma once
// crazyflie_mellinger: the control law of crazyflie-firmware's controller_mellinger.c (Mellinger
// and Kumar 2011, "Minimum snap trajectory generation and control for quadrotors", ICRA, eqs.
// 6-7 and the moment law of their section IV), with the firmware's default gains, run at 500 Hz
// (ATTITUDE_RATE), in its legacy control mode (thrust and moments on the 16-bit PWM scale).
// With z up, e_p = p_d - p, e_v = v_d - v, and the believed mass m:
//   F_des = m (a_d + g e3) + K_p e_p + K_v e_v + K_i int(e_p)    (N; int clamped per axis)
//   T     = F_des . z_B                                           (eq. 6's u_1)
//   R_des: z_B,des = F_des / |F_des|, x from the yaw as in eq. 7's construction
//   e_R   = vee(R_des^T R - R^T R_des)                            (no 1/2, as the firmware)
//   e_w   = w_des - w, w_des the high-level commander's rates from the reference's jerk
//           (highLevelCommanderRates; the law itself does not use the jerk)
//   M     = -K_R e_R + K_w e_w + K_I int(-e_R) + K_d,rp d(e_w)/dt (roll and pitch only)
// Outputs: thrust = massThrust T (PWM per newton of collective thrust), each moment clamped to
// +-32000, as the firmware hands them to its legacy power distribution. The gains were tuned for
// the brushed Crazyflie 2.x; on the Brushless build the same PWM numbers mean other forces (its
// THRUST_MAX scale): the firmware's default behaviour on this platform, kept as it is.
// The believed mass m: ctrlMel.mass if given, else the airframe's (CrazyflieMassBasedController).
#include "control/crazyflie_firmware_controller.h"

namespace cosim {

// controller_mellinger.c's g_self defaults (ctrlMel parameters).
struct CrazyflieMellingerGains {
  double mass = -1.0;           // ctrlMel.mass, kg; negative: the given airframe's mass
  double mass_thrust = 132000;  // massThrust, PWM per N
  double kp_xy = 0.4, kd_xy = 0.2, ki_xy = 0.05, i_range_xy = 2.0;  // N/m, N s/m, N/(m s), m s
  double kp_z = 1.25, kd_z = 0.4, ki_z = 0.05, i_range_z = 0.4;
  double kR_xy = 70000, kw_xy = 20000, ki_m_xy = 0.0, i_range_m_xy = 1.0;  // PWM per unit
  double kR_z = 60000, kw_z = 12000, ki_m_z = 500, i_range_m_z = 1500;
  double kd_omega_rp = 200;  // PWM per rad/s^2
};

class CrazyflieMellingerController : public CrazyflieMassBasedController<CrazyflieMellingerGains> {
 public:
  CrazyflieMellingerController(const QuadrotorParams& airframe,
                               const CrazyflieMellingerGains& gains = {},
                               const CrazyfliePlatform& platform = crazyflie21BrushlessPlatform());
  static constexpr char kName[] = "crazyflie_mellinger";
  std::string name() const override { return kName; }

  // One 500 Hz step: the legacy command, right-handed moments (roll, pitch, yaw about body x, y,
  // z) before the firmware's sign conventions are applied (exposed for tests).
  struct Command {
    double thrust_pwm = 0.0;                          // massThrust T
    Eigen::Vector3d force = Eigen::Vector3d::Zero();  // F_des, N
    Eigen::Vector3d e_R = Eigen::Vector3d::Zero();
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // PWM scale, clamped
  };
  Command law(const VehicleState& state, const FlatReference& setpoint);

 protected:
  Eigen::Vector4d lawStep(const VehicleState& state, const FlatReference& setpoint,
                          const CrazyflieClock& clock) override;
  void resetLaw() override;
  bool legacyMode() const override { return true; }

 private:
  Eigen::Vector3d i_error_ = Eigen::Vector3d::Zero();    // of e_p, m s
  Eigen::Vector3d i_error_m_ = Eigen::Vector3d::Zero();  // of -e_R, s
  Eigen::Vector2d prev_rate_error_ = Eigen::Vector2d::Zero();
  bool has_prev_ = false;
};

class ControllerRegistry;
// Registers crazyflie_mellinger (its gains, team margin, ...) in the controller registry.
void registerCrazyflieMellingerController(ControllerRegistry& registry);

}  // namespace cosim
