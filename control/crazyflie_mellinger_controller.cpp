#include "control/crazyflie_mellinger_controller.h"

#include <algorithm>
#include <cmath>

#include "control/controller_registry.h"
#include "control/vee_map.h"

namespace cosim {

CrazyflieMellingerController::CrazyflieMellingerController(const QuadrotorParams& airframe,
                                                           const CrazyflieMellingerGains& gains,
                                                           const CrazyfliePlatform& platform)
    : CrazyflieMassBasedController(airframe, gains, platform) {}

void CrazyflieMellingerController::resetLaw() {
  i_error_.setZero();
  i_error_m_.setZero();
  prev_rate_error_.setZero();
  has_prev_ = false;
}

CrazyflieMellingerController::Command CrazyflieMellingerController::law(const VehicleState& s,
                                                                        const FlatReference& sp) {
  const double dt = 1.0 / kCrazyflieAttitudeRate;
  const CrazyflieMellingerGains& k = gains_;
  Command c;

  // Position: integral per axis, clamped to its range.
  const Eigen::Vector3d r_e = sp.position - s.position;
  const Eigen::Vector3d v_e = sp.velocity - s.velocity;
  i_error_ += dt * r_e;
  i_error_.x() = std::clamp(i_error_.x(), -k.i_range_xy, k.i_range_xy);
  i_error_.y() = std::clamp(i_error_.y(), -k.i_range_xy, k.i_range_xy);
  i_error_.z() = std::clamp(i_error_.z(), -k.i_range_z, k.i_range_z);
  const Eigen::Vector3d kp(k.kp_xy, k.kp_xy, k.kp_z), kd(k.kd_xy, k.kd_xy, k.kd_z),
      ki(k.ki_xy, k.ki_xy, k.ki_z);
  c.force = mass_ * (sp.acceleration + platform_.gravity * Eigen::Vector3d::UnitZ()) +
            kp.cwiseProduct(r_e) + kd.cwiseProduct(v_e) + ki.cwiseProduct(i_error_);
  const Eigen::Matrix3d R = s.attitude.toRotationMatrix();
  const double thrust = c.force.dot(R.col(2));

  // Desired attitude.
  Eigen::Matrix3d R_d;
  R_d.col(2) = c.force.normalized();
  const Eigen::Vector3d xc(std::cos(sp.yaw), std::sin(sp.yaw), 0.0);
  R_d.col(1) = R_d.col(2).cross(xc).normalized();
  R_d.col(0) = R_d.col(1).cross(R_d.col(2));
  c.e_R = vee(R_d.transpose() * R - R.transpose() * R_d);

  // Rates: the high-level commander's (from the reference's jerk); the roll and pitch rate
  // errors' derivative (the set-point's part changes at 100 Hz, as in the firmware).
  const Eigen::Vector3d e_w = highLevelCommanderRates(sp, platform_.gravity) - s.angular_velocity;
  Eigen::Vector2d d_e_w = Eigen::Vector2d::Zero();
  if (has_prev_) d_e_w = (e_w.head<2>() - prev_rate_error_) / dt;
  prev_rate_error_ = e_w.head<2>();
  has_prev_ = true;

  i_error_m_ -= dt * c.e_R;
  i_error_m_.x() = std::clamp(i_error_m_.x(), -k.i_range_m_xy, k.i_range_m_xy);
  i_error_m_.y() = std::clamp(i_error_m_.y(), -k.i_range_m_xy, k.i_range_m_xy);
  i_error_m_.z() = std::clamp(i_error_m_.z(), -k.i_range_m_z, k.i_range_m_z);
  const Eigen::Vector3d kR(k.kR_xy, k.kR_xy, k.kR_z), kw(k.kw_xy, k.kw_xy, k.kw_z),
      kim(k.ki_m_xy, k.ki_m_xy, k.ki_m_z);
  Eigen::Vector3d M = -kR.cwiseProduct(c.e_R) + kw.cwiseProduct(e_w) + kim.cwiseProduct(i_error_m_);
  M.head<2>() += k.kd_omega_rp * d_e_w;

  c.thrust_pwm = k.mass_thrust * thrust;
  c.moment = Eigen::Vector3d::Zero();
  if (c.thrust_pwm > 0.0) c.moment = M.cwiseMax(-32000.0).cwiseMin(32000.0);
  return c;
}

Eigen::Vector4d CrazyflieMellingerController::lawStep(const VehicleState& s,
                                                      const FlatReference& sp,
                                                      const CrazyflieClock&) {
  const Command c = law(s, sp);
  // The firmware's legacy signs: pitch positive nose up (-M_y), yaw command -M_z.
  return crazyflieLegacyMix(platform_, c.thrust_pwm, c.moment.x(), -c.moment.y(), -c.moment.z());
}

namespace {

const GainTable<CrazyflieMellingerGains>& crazyflieMellingerGains() {
  using G = CrazyflieMellingerGains;
  static const GainTable<G> table =
      GainTable<G>()
          .optionalGain("mass", &G::mass, kBelievedMassMin, kBelievedMassMax,
                        "ctrlMel.mass: the mass the firmware believes, kg", "the airframe's")
          .gain("mass_thrust", &G::mass_thrust, 0.0, 1e7, "massThrust: PWM per N")
          .gain("kp_xy", &G::kp_xy, 0.0, 1e3, "horizontal position error, N/m")
          .gain("kd_xy", &G::kd_xy, 0.0, 1e3, "horizontal velocity error, N s/m")
          .gain("ki_xy", &G::ki_xy, 0.0, 1e3, "horizontal position-error integral, N/(m s)")
          .gain("kp_z", &G::kp_z, 0.0, 1e3, "vertical position error, N/m")
          .gain("kd_z", &G::kd_z, 0.0, 1e3, "vertical velocity error, N s/m")
          .gain("ki_z", &G::ki_z, 0.0, 1e3, "vertical position-error integral, N/(m s)")
          .gain("kr_xy", &G::kR_xy, 0.0, 1e7, "roll and pitch attitude error, PWM per unit")
          .gain("kw_xy", &G::kw_xy, 0.0, 1e7, "roll and pitch rate error, PWM per rad/s")
          .gain("kr_z", &G::kR_z, 0.0, 1e7, "yaw attitude error, PWM per unit")
          .gain("kw_z", &G::kw_z, 0.0, 1e7, "yaw rate error, PWM per rad/s")
          .gain("ki_m_z", &G::ki_m_z, 0.0, 1e7, "yaw attitude-error integral, PWM per (unit s)")
          .gain("kd_omega_rp", &G::kd_omega_rp, 0.0, 1e7,
                "roll and pitch rate error's change, PWM per rad/s^2");
  return table;
}

}  // namespace

void registerCrazyflieMellingerController(ControllerRegistry& registry) {
  ControllerEntry e;
  e.name = CrazyflieMellingerController::kName;
  e.summary = "crazyflie-firmware's controller_mellinger.c (Mellinger and Kumar 2011) at 500 Hz";
  e.gains = crazyflieMellingerGains().declarations();
  e.team_shortfall = 0.05;  // swarm32 1.45, dense 1.47
  e.crazyflie_thrust_path = true;
  e.make = [](const QuadrotorParams& params, ParamSet& gains,
              const ControllerOptions& options) -> std::unique_ptr<FlightController> {
    auto c = std::make_unique<CrazyflieMellingerController>(params,
                                                            crazyflieMellingerGains().read(gains));
    c->setThrustPath(options.thrust_path);
    return c;
  };
  registry.add(std::move(e));
}

}  // namespace cosim
