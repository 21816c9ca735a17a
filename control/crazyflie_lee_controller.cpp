#include "control/crazyflie_lee_controller.h"

#include <cmath>

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
    : CrazyflieFirmwareController(airframe, platform),
      gains_(gains),
      mass_(gains.mass > 0.0 ? gains.mass : airframe.mass) {}

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

}  // namespace cosim
