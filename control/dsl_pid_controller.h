#pragma once
// The PID baseline of gym-pybullet-drones (Panerati et al. 2021, "Learning to fly: a Gym
// environment with PyBullet physics for reinforcement learning of multi-agent quadcopter
// control", IROS; gym_pybullet_drones/control/DSLPIDControl.py, after UTIAS DSL's Crazyflie
// controller), generalised from the Crazyflie 2.x it was tuned for to any airframe:
//   position  F = P e + I int(e) + D e_v + [0, 0, m g]   (e = x_ref - x, e_v = v_ref - v; no
//             reference-acceleration feed-forward), int(e) clipped to +-2 m s (z +-0.15);
//             collective thrust F . z_B (its projection on the current body z)
//   attitude  R_d: z along F, x_c = [cos yaw, sin yaw, 0]; rot_e = vee(R_d^T R - R^T R_d) (no 1/2)
//             rate error = target rpy rates - (rpy - rpy_prev) / dt (finite differences of the
//             roll, pitch and yaw over the control step; the gyro is not used)
//             torque = -P rot_e + D rate_e + I int(-rot_e), int clipped to +-1500 (roll and
//             pitch +-1), torque clipped to +-3200
// with the original gains (DslPidGains) in their original units: N per m (and per m s, per m/s)
// for the 27 g CF2X, and the CF2X's PWM for the torques.
//
// How the gains are carried to another airframe (dslAccelerationGains): each gain becomes an
// acceleration gain by linearising the CF2X's own chain at hover, then is scaled by the
// airframe's mass and inertia. Force gains are divided by the CF2X's mass. A torque of u PWM
// changes each motor's PWM by 0.5 u (roll, pitch) or u (yaw) (the CF2X MIXER_MATRIX), hence its
// speed by PWM2RPM_SCALE times that, its thrust by dT/dPWM = 2 K_F rpm_h PWM2RPM_SCALE and its
// drag torque by 2 K_M rpm_h PWM2RPM_SCALE; four motors at arm / sqrt(2) (roll, pitch) or four
// drag torques (yaw), over the CF2X inertia, give rad/s^2 per PWM. All of it is computed from the
// named CF2X constants in dsl_pid_controller.cpp.
//
// Where this deviates from DSLPIDControl.py, and why:
// - Thrusts and torques go through Mixer::allocateLimited on the airframe's own geometry and
//   thrust range (priorities: roll/pitch, then thrust, then yaw) instead of the CF2X's PWM mixer
//   clipped motor by motor to PWM 20000..65535: the PWM chain exists only on the CF2X. The
//   collective thrust is exact (the original inverts its PWM -> thrust map exactly too); the
//   torques use the map linearised at hover, exact to first order.
// - The yaw difference for the rate is wrapped to (-pi, pi] (the original jumps by 2 pi / dt,
//   a full-scale torque kick, whenever the yaw crosses +-pi), and the first update after a reset
//   takes the rates as zero (the original differences against rpy = 0, a kick when the vehicle
//   starts banked or yawed).
// - The target rpy rates are (0, 0, reference yaw rate); gym-pybullet-drones' examples pass zero.
// Kept as in the original although a careful design would not: no acceleration feed-forward (the
// baseline lags fast trajectories), no tilt limit (a large downward position error commands an
// inverted attitude), Euler-angle rate differences in place of body rates.
#include "control/flight_controller.h"
#include "control/mixer.h"

namespace cosim {

// DSLPIDControl.py's coefficients, in its units (the CF2X's N and PWM).
struct DslPidGains {
  Eigen::Vector3d p_for{0.4, 0.4, 1.25};             // P_COEFF_FOR, N/m
  Eigen::Vector3d i_for{0.05, 0.05, 0.05};           // I_COEFF_FOR, N/(m s)
  Eigen::Vector3d d_for{0.2, 0.2, 0.5};              // D_COEFF_FOR, N/(m/s)
  double i_pos_limit_xy = 2.0;                       // m s, bound on the position-error integral
  double i_pos_limit_z = 0.15;                       // m s
  Eigen::Vector3d p_tor{70000.0, 70000.0, 60000.0};  // P_COEFF_TOR, PWM per unit of rot_e
  Eigen::Vector3d i_tor{0.0, 0.0, 500.0};            // I_COEFF_TOR, PWM per (unit s)
  Eigen::Vector3d d_tor{20000.0, 20000.0, 12000.0};  // D_COEFF_TOR, PWM per rad/s
  double i_rpy_limit_rp = 1.0;  // bound on the attitude-error integral, roll and pitch
  double i_rpy_limit_yaw = 1500.0;
  double max_torque_pwm = 3200.0;  // bound on each torque command, PWM
};

// The same gains per unit mass and inertia, for any airframe.
struct DslAccelerationGains {
  Eigen::Vector3d k_p, k_i, k_d;  // 1/s^2, 1/s^3, 1/s: position loop, per unit mass
  Eigen::Vector3d k_R, k_I, k_w;  // 1/s^2 per unit rot_e, 1/s^3, 1/s: attitude loop, per inertia
  Eigen::Vector3d alpha_max;      // rad/s^2: the torque clip
};
DslAccelerationGains dslAccelerationGains(const DslPidGains& gains);

class DslPidController : public FlightController {
 public:
  DslPidController(const QuadrotorParams& params, const DslPidGains& gains = {});
  static constexpr char kName[] = "dsl_pid";
  std::string name() const override { return kName; }
  void reset() override;
  ControlOutput update(const VehicleState& state, const FlatReference& ref, double dt) override;

  const DslAccelerationGains& accelerationGains() const { return k_; }
  // For logging: the last target attitude (body to world).
  const Eigen::Matrix3d& desiredAttitude() const { return R_d_; }

 private:
  QuadrotorParams params_;
  DslPidGains gains_;
  DslAccelerationGains k_;
  Mixer mixer_;
  Eigen::Vector3d integral_pos_e_ = Eigen::Vector3d::Zero();  // m s
  Eigen::Vector3d integral_rpy_e_ = Eigen::Vector3d::Zero();  // of -rot_e, s
  Eigen::Vector3d last_rpy_ = Eigen::Vector3d::Zero();        // rad
  bool has_last_rpy_ = false;
  Eigen::Matrix3d R_d_ = Eigen::Matrix3d::Identity();
};

class ControllerRegistry;
// Registers dsl_pid (its gains, team margin, ...) in the controller registry.
void registerDslPidController(ControllerRegistry& registry);

}  // namespace cosim
