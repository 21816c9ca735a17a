#include "control/crazyflie_lee_controller.h"

#include <cmath>

#include "control/controller_registry.h"
#include "control/vee_map.h"

namespace cosim {

namespace {

Eigen::Vector3d clampEach(const Eigen::Vector3d& v, double limit) {
  return v.cwiseMax(-limit).cwiseMin(limit);
}

}  // namespace

CrazyflieLeeController::CrazyflieLeeController(const QuadrotorParams& airframe,
                                               const CrazyflieLeeGains& gains,
                                               const CrazyfliePlatform& platform)
    : CrazyflieMassBasedController(airframe, gains, platform) {}

void CrazyflieLeeController::resetLaw() {
  i_error_pos_.setZero();
  i_error_att_.setZero();
}

CrazyflieLeeController::Command CrazyflieLeeController::law(const VehicleState& s,
                                                            const FlatReference& sp) {
  const double dt = 1.0 / kCrazyflieAttitudeRate;
  const Eigen::Vector3d e3 = Eigen::Vector3d::UnitZ();
  const Eigen::Matrix3d R = s.attitude.toRotationMatrix();
  Command c;

  // Position part: the desired force per unit mass (Lee et al. eq. 15 with z up).
  const Eigen::Vector3d pos_e = clampEach(sp.position - s.position, gains_.kpos_p_limit);
  const Eigen::Vector3d vel_e = clampEach(sp.velocity - s.velocity, gains_.kpos_d_limit);
  i_error_pos_ += dt * pos_e;
  const Eigen::Vector3d F_d =
      sp.acceleration + platform_.gravity * e3 + gains_.kpos_d.cwiseProduct(vel_e) +
      gains_.kpos_p.cwiseProduct(pos_e) + gains_.kpos_i.cwiseProduct(i_error_pos_);
  c.thrust = mass_ * F_d.dot(R.col(2));
  if (c.thrust < 0.01) resetLaw();  // on the ground: no accumulated error

  // Desired attitude: b3 along F_d (level while the thrust is not positive), b1 from the yaw.
  Eigen::Vector3d zdes = e3, ydes = Eigen::Vector3d::UnitY();
  if (c.thrust > 0.0) zdes = F_d.normalized();
  const Eigen::Vector3d xc(std::cos(sp.yaw), std::sin(sp.yaw), 0.0);
  const Eigen::Vector3d zx = zdes.cross(xc);
  if (zx.norm() > 0.0) ydes = zx.normalized();
  const Eigen::Vector3d xdes = ydes.cross(zdes);
  c.R_d.col(0) = xdes;
  c.R_d.col(1) = ydes;
  c.R_d.col(2) = zdes;

  // Attitude part: error on SO(3), desired rates from the jerk, moment.
  const Eigen::Vector3d e_R = 0.5 * vee(c.R_d.transpose() * R - R.transpose() * c.R_d);
  Eigen::Vector3d hw = Eigen::Vector3d::Zero();
  if (c.thrust != 0.0) hw = mass_ / c.thrust * (sp.jerk - zdes.dot(sp.jerk) * zdes);
  // The yaw rate is the set-point's (already z_b,z times the reference's, pptraj.c), again
  // times b3d . e3 as controller_lee.c does.
  const double yaw_rate = highLevelCommanderRates(sp, platform_.gravity).z();
  const Eigen::Vector3d omega_des(-hw.dot(ydes), hw.dot(xdes), yaw_rate * zdes.dot(e3));
  const Eigen::Vector3d omega_r = R.transpose() * c.R_d * omega_des;
  const Eigen::Vector3d& w = s.angular_velocity;
  i_error_att_ += dt * e_R;
  c.torque = -gains_.k_r.cwiseProduct(e_R) - gains_.k_omega.cwiseProduct(w - omega_r) -
             gains_.k_i.cwiseProduct(i_error_att_) + w.cross(gains_.inertia.cwiseProduct(w));
  return c;
}

Eigen::Vector4d CrazyflieLeeController::lawStep(const VehicleState& s, const FlatReference& sp,
                                                const CrazyflieClock&) {
  const Command c = law(s, sp);
  return crazyflieForceTorqueMix(platform_, c.thrust, c.torque);
}

namespace {

// x and y share one gain; z has its own (the firmware's defaults are symmetric in x and y).
const GainTable<CrazyflieLeeGains>& crazyflieLeeGains() {
  using G = CrazyflieLeeGains;
  static const GainTable<G> table =
      GainTable<G>()
          .horizontalAndZ("kpos_p", &G::kpos_p, 1e4, "Kpos_P: position error, 1/s^2")
          .horizontalAndZ("kpos_d", &G::kpos_d, 1e4, "Kpos_D: velocity error, 1/s")
          .horizontalAndZ("kpos_i", &G::kpos_i, 1e4, "Kpos_I: position-error integral, 1/s^3")
          .gain("kpos_p_limit", &G::kpos_p_limit, 0.0, 1e4,
                "Kpos_P_limit: bound on each position error, m")
          .gain("kpos_d_limit", &G::kpos_d_limit, 0.0, 1e4,
                "Kpos_D_limit: bound on each velocity error, m/s")
          .horizontalAndZ("kr", &G::k_r, 10.0, "KR: N m per unit of attitude error")
          .horizontalAndZ("komega", &G::k_omega, 10.0, "Komega: N m per rad/s of rate error")
          .horizontalAndZ("ki", &G::k_i, 10.0, "KI: N m per (unit of attitude error s)")
          .optionalGain("mass", &G::mass, kBelievedMassMin, kBelievedMassMax,
                        "ctrlLee.mass: the mass the firmware believes, kg", "the airframe's");
  return table;
}

}  // namespace

void registerCrazyflieLeeController(ControllerRegistry& registry) {
  ControllerEntry e;
  e.name = CrazyflieLeeController::kName;
  e.summary = "crazyflie-firmware's controller_lee.c (Lee, Leok and McClamroch 2010) at 500 Hz";
  e.gains = crazyflieLeeGains().declarations();
  e.team_shortfall = 0.05;  // swarm32 1.45, dense 1.48
  e.crazyflie_thrust_path = true;
  e.make = [](const QuadrotorParams& params, ParamSet& gains,
              const ControllerOptions& options) -> std::unique_ptr<FlightController> {
    auto c = std::make_unique<CrazyflieLeeController>(params, crazyflieLeeGains().read(gains));
    c->setThrustPath(options.thrust_path);
    return c;
  };
  registry.add(std::move(e));
}

}  // namespace cosim
