#pragma once
// crazyflie_lee: the control law of crazyflie-firmware's controller_lee.c, the geometric tracking
// control on SE(3) of Lee, Leok and McClamroch 2010 ("Geometric tracking control of a quadrotor
// UAV on SE(3)", CDC), with the firmware's default gains, run at 500 Hz (ATTITUDE_RATE), in its
// force/torque control mode. With z up, e_x = x_d - x, e_v = v_d - v (both clamped to the
// *_limit gains), per unit of the believed mass m:
//   F_d = a_d + g e3 + K_v e_v + K_x e_x + K_i int(e_x)          (paper eq. 15, signs for z up)
//   T   = m F_d . R e3                                           (collective thrust, N)
//   R_d: b3d = F_d / |F_d|, b1d from the yaw, b2d = b3d x b1c / |.|, b1d = b2d x b3d
//   e_R = vee(R_d^T R - R^T R_d) / 2                             (eq. 10)
//   h_w = m / T (j_d - (b3d . j_d) b3d);  w_d = (-h_w . b2d, h_w . b1d, yaw_rate b3d . e3)
//                                                                (desired rates from the jerk,
//                                                                 Mellinger and Kumar 2011 eq. 7)
//   M   = -K_R e_R - K_w (w - R^T R_d w_d) - K_I int(e_R) + w x J w
// The gains of the moment are in N m (not scaled by an inertia): on a heavier airframe the same
// gains turn it more slowly, as on the real vehicle. Where the firmware departs from the paper it
// is followed: the moment drops the paper's -J (w^ R^T R_d w_d - R^T R_d dw_d) term, the
// integrals are not bounded (Kpos_I_limit is declared but unused; Kpos_I is 0 by default), both
// integrals reset whenever T < 0.01 N, and no tilt limit applies.
// The believed mass m: ctrlLee.mass if given, else the airframe's (CrazyflieMassBasedController).
#include "control/crazyflie_firmware_controller.h"

namespace cosim {

// controller_lee.c's g_self defaults (ctrlLee parameters).
struct CrazyflieLeeGains {
  Eigen::Vector3d kpos_p{7.0, 7.0, 7.0};     // Kpos_P, 1/s^2
  Eigen::Vector3d kpos_d{4.0, 4.0, 4.0};     // Kpos_D, 1/s
  Eigen::Vector3d kpos_i{0.0, 0.0, 0.0};     // Kpos_I, 1/s^3
  double kpos_p_limit = 100.0;               // Kpos_P_limit, m: bound on each position error
  double kpos_d_limit = 100.0;               // Kpos_D_limit, m/s: bound on each velocity error
  Eigen::Vector3d k_r{0.007, 0.007, 0.008};  // KR, N m per unit e_R
  Eigen::Vector3d k_omega{0.00115, 0.00115, 0.002};  // Komega, N m per rad/s
  Eigen::Vector3d k_i{0.03, 0.03, 0.03};             // KI, N m per (unit e_R s)
  // J: Foerster 2015's Crazyflie 2.0 inertia, kg m^2 (used only in w x J w).
  Eigen::Vector3d inertia{16.571710e-6, 16.655602e-6, 29.261652e-6};
  double mass = -1.0;  // ctrlLee.mass, kg; negative: the given airframe's mass (configured)
};

class CrazyflieLeeController : public CrazyflieMassBasedController<CrazyflieLeeGains> {
 public:
  CrazyflieLeeController(const QuadrotorParams& airframe, const CrazyflieLeeGains& gains = {},
                         const CrazyfliePlatform& platform = crazyflie21BrushlessPlatform());
  static constexpr char kName[] = "crazyflie_lee";
  std::string name() const override { return kName; }

  // One 500 Hz step of the law: collective thrust (N) and moment (N m), as the firmware hands
  // them to its power distribution (exposed for tests).
  struct Command {
    double thrust = 0.0;
    Eigen::Vector3d torque = Eigen::Vector3d::Zero();
    Eigen::Matrix3d R_d = Eigen::Matrix3d::Identity();
  };
  Command law(const VehicleState& state, const FlatReference& setpoint);

 protected:
  Eigen::Vector4d lawStep(const VehicleState& state, const FlatReference& setpoint,
                          const CrazyflieClock& clock) override;
  void resetLaw() override;
  bool legacyMode() const override { return false; }

 private:
  Eigen::Vector3d i_error_pos_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d i_error_att_ = Eigen::Vector3d::Zero();
};

class ControllerRegistry;
// Registers crazyflie_lee (its gains, team margin, ...) in the controller registry.
void registerCrazyflieLeeController(ControllerRegistry& registry);

}  // namespace cosim
