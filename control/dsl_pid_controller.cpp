#include "control/dsl_pid_controller.h"

#include <algorithm>
#include <cmath>

#include "control/controller_registry.h"
#include "control/thrust_direction.h"
#include "control/vee_map.h"

namespace cosim {
namespace {

// The CF2X of gym-pybullet-drones (gym_pybullet_drones/assets/cf2x.urdf) and the PWM chain of
// DSLPIDControl.py that its gains were tuned on.
namespace cf2x {
constexpr double kMass = 0.027;   // kg
constexpr double kGravity = 9.8;  // m/s^2, BaseControl's default g
constexpr double kKf = 3.16e-10;  // N/rpm^2: thrust = K_F rpm^2
constexpr double kKm = 7.94e-12;  // N m/rpm^2: drag torque = K_M rpm^2
constexpr double kArm = 0.0397;   // m, centre to motor
constexpr double kIxx = 1.4e-5, kIyy = 1.4e-5, kIzz = 2.17e-5;  // kg m^2
constexpr double kPwm2RpmScale = 0.2685;  // rpm = PWM2RPM_SCALE pwm + PWM2RPM_CONST
// MIXER_MATRIX (CF2X): each motor's PWM moves by +-0.5 of the roll and pitch commands and by
// +-1 of the yaw command; with x_torque = (f0 + f1 - f2 - f3) L / sqrt(2) and z_torque =
// -q0 + q1 - q2 + q3 (BaseAviary._dynamics) a positive command gives a positive torque.
constexpr double kMixRollPitch = 0.5;
constexpr double kMixYaw = 1.0;
}  // namespace cf2x

// Roll, pitch, yaw with R = Rz(yaw) Ry(pitch) Rx(roll), as pybullet's getEulerFromQuaternion.
Eigen::Vector3d rollPitchYaw(const Eigen::Matrix3d& R) {
  return {std::atan2(R(2, 1), R(2, 2)), std::asin(std::clamp(-R(2, 0), -1.0, 1.0)),
          std::atan2(R(1, 0), R(0, 0))};
}

double angleRemainder(double a) {
  return std::remainder(a, 2.0 * M_PI);
}

}  // namespace

DslAccelerationGains dslAccelerationGains(const DslPidGains& g) {
  using namespace cf2x;
  // Linearised at hover: each motor carries a quarter of the weight.
  const double rpm_hover = std::sqrt(kMass * kGravity / (4.0 * kKf));
  const double thrust_per_pwm = 2.0 * kKf * rpm_hover * kPwm2RpmScale;       // N per PWM, one motor
  const double drag_torque_per_pwm = 2.0 * kKm * rpm_hover * kPwm2RpmScale;  // N m per PWM
  const double lever = kArm / std::sqrt(2.0);
  const Eigen::Vector3d alpha_per_pwm(4.0 * kMixRollPitch * thrust_per_pwm * lever / kIxx,
                                      4.0 * kMixRollPitch * thrust_per_pwm * lever / kIyy,
                                      4.0 * kMixYaw * drag_torque_per_pwm / kIzz);
  DslAccelerationGains k;
  k.k_p = g.p_for / kMass;
  k.k_i = g.i_for / kMass;
  k.k_d = g.d_for / kMass;
  k.k_R = g.p_tor.cwiseProduct(alpha_per_pwm);
  k.k_I = g.i_tor.cwiseProduct(alpha_per_pwm);
  k.k_w = g.d_tor.cwiseProduct(alpha_per_pwm);
  k.alpha_max = g.max_torque_pwm * alpha_per_pwm;
  return k;
}

DslPidController::DslPidController(const QuadrotorParams& params, const DslPidGains& gains)
    : params_(params), gains_(gains), k_(dslAccelerationGains(gains)), mixer_(params) {}

void DslPidController::reset() {
  integral_pos_e_.setZero();
  integral_rpy_e_.setZero();
  last_rpy_.setZero();
  has_last_rpy_ = false;
  R_d_.setIdentity();
}

ControlOutput DslPidController::update(const VehicleState& s, const FlatReference& ref, double dt) {
  const Eigen::Matrix3d R = s.attitude.toRotationMatrix();

  // Position PID (_dslPIDPositionControl), per unit mass.
  const Eigen::Vector3d pos_e = ref.position - s.position;
  const Eigen::Vector3d vel_e = ref.velocity - s.velocity;
  integral_pos_e_ += pos_e * dt;
  integral_pos_e_ =
      integral_pos_e_.cwiseMax(-gains_.i_pos_limit_xy).cwiseMin(gains_.i_pos_limit_xy);
  integral_pos_e_.z() =
      std::clamp(integral_pos_e_.z(), -gains_.i_pos_limit_z, gains_.i_pos_limit_z);
  const Eigen::Vector3d target_thrust =
      k_.k_p.cwiseProduct(pos_e) + k_.k_i.cwiseProduct(integral_pos_e_) +
      k_.k_d.cwiseProduct(vel_e) + params_.gravity * Eigen::Vector3d::UnitZ();
  const double scalar_thrust = std::max(0.0, params_.mass * target_thrust.dot(R.col(2)));

  // Target attitude: z along the target thrust, x_c from the reference yaw. (Only a zero
  // thrust vector, which the original would divide by, falls back to level.)
  R_d_ = attitudeAlong(target_thrust.norm() > 1e-9 ? target_thrust : Eigen::Vector3d::UnitZ(),
                       ref.yaw);

  // Attitude PID (_dslPIDAttitudeControl), per unit inertia.
  const Eigen::Vector3d rot_e = vee(R_d_.transpose() * R - R.transpose() * R_d_);
  const Eigen::Vector3d rpy = rollPitchYaw(R);
  Eigen::Vector3d rpy_rates = Eigen::Vector3d::Zero();
  if (has_last_rpy_)
    for (int i = 0; i < 3; ++i) rpy_rates[i] = angleRemainder(rpy[i] - last_rpy_[i]) / dt;
  last_rpy_ = rpy;
  has_last_rpy_ = true;
  const Eigen::Vector3d rpy_rates_e = Eigen::Vector3d(0.0, 0.0, ref.yaw_rate) - rpy_rates;
  integral_rpy_e_ -= rot_e * dt;
  integral_rpy_e_ =
      integral_rpy_e_.cwiseMax(-gains_.i_rpy_limit_yaw).cwiseMin(gains_.i_rpy_limit_yaw);
  for (int i = 0; i < 2; ++i)
    integral_rpy_e_[i] =
        std::clamp(integral_rpy_e_[i], -gains_.i_rpy_limit_rp, gains_.i_rpy_limit_rp);
  const Eigen::Vector3d alpha = (-k_.k_R.cwiseProduct(rot_e) + k_.k_w.cwiseProduct(rpy_rates_e) +
                                 k_.k_I.cwiseProduct(integral_rpy_e_))
                                    .cwiseMax(-k_.alpha_max)
                                    .cwiseMin(k_.alpha_max);

  ControlOutput out;
  out.collective_thrust = scalar_thrust;
  out.torque = params_.inertia.cwiseProduct(alpha);
  out.rotor_thrusts = mixer_.allocateLimited(scalar_thrust, out.torque, &out.saturated);
  return out;
}

namespace {

// In DSLPIDControl.py's own units (the CF2X's N and PWM; see dsl_pid_controller.h).
const GainTable<DslPidGains>& dslPidGains() {
  using G = DslPidGains;
  static const GainTable<G> table =
      GainTable<G>()
          .horizontalAndZ("p_for", &G::p_for, 1e3, "P_COEFF_FOR: position error -> force, N/m")
          .horizontalAndZ("i_for", &G::i_for, 1e3,
                          "I_COEFF_FOR: position-error integral -> force, N/(m s)")
          .horizontalAndZ("d_for", &G::d_for, 1e3, "D_COEFF_FOR: velocity error -> force, N/(m/s)")
          .gain("i_pos_limit_xy", &G::i_pos_limit_xy, 0.0, 1e3,
                "bound on the horizontal position-error integral, m s")
          .gain("i_pos_limit_z", &G::i_pos_limit_z, 0.0, 1e3,
                "bound on the vertical position-error integral, m s")
          .rollPitchAndYaw("p_tor", &G::p_tor, 1e7, "P_COEFF_TOR: PWM per unit of rot_e")
          .rollPitchAndYaw("i_tor", &G::i_tor, 1e7, "I_COEFF_TOR: PWM per (unit of rot_e s)")
          .rollPitchAndYaw("d_tor", &G::d_tor, 1e7, "D_COEFF_TOR: PWM per rad/s")
          .gain("i_rpy_limit_rp", &G::i_rpy_limit_rp, 0.0, 1e4,
                "bound on the roll and pitch attitude-error integral")
          .gain("i_rpy_limit_yaw", &G::i_rpy_limit_yaw, 0.0, 1e4,
                "bound on the yaw attitude-error integral")
          .gain("max_torque_pwm", &G::max_torque_pwm, 0.0, 65535.0,
                "bound on each torque command, PWM");
  return table;
}

}  // namespace

void registerDslPidController(ControllerRegistry& registry) {
  ControllerEntry e;
  e.name = DslPidController::kName;
  e.summary = "gym-pybullet-drones' DSLPIDControl (Panerati et al. 2021), for any airframe";
  e.gains = dslPidGains().declarations();
  e.team_shortfall = 0.58;  // swarm32 1.30; dense 1.09, and 0.94 planned at 1.51
  e.make = [](const QuadrotorParams& params, ParamSet& gains,
              const ControllerOptions&) -> std::unique_ptr<FlightController> {
    return std::make_unique<DslPidController>(params, dslPidGains().read(gains));
  };
  registry.add(std::move(e));
}

}  // namespace cosim
