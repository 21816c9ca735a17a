#include "control/cascade_controller.h"

#include <algorithm>
#include <cmath>

#include "control/controller_registry.h"

namespace cosim {

CascadeController::CascadeController(const QuadrotorParams& params, const CascadeGains& gains)
    : params_(params), gains_(gains), mixer_(params) {
  for (int i = 0; i < 3; ++i) {
    vel_pid_[i] = Pid({gains.vel_kp, gains.vel_ki, 0.0, gains.vel_i_limit});
    rate_pid_[i] = Pid({gains.rate_kp[i], gains.rate_ki[i], 0.0, gains.rate_i_limit[i]});
  }
}

void CascadeController::reset() {
  for (int i = 0; i < 3; ++i) {
    vel_pid_[i].reset();
    rate_pid_[i].reset();
    accel_saturated_[i] = rate_saturated_[i] = 0;
  }
}

ControlOutput CascadeController::update(const VehicleState& s, const FlatReference& ref,
                                        double dt) {
  const Eigen::Vector3d e3 = Eigen::Vector3d::UnitZ();
  const double g = params_.gravity;

  // Position loop: P on position plus the reference velocity, limited to the speed limits.
  Eigen::Vector3d v_cmd = gains_.pos_kp * (ref.position - s.position) + ref.velocity;
  const double vxy = v_cmd.head<2>().norm();
  if (vxy > gains_.max_speed_xy) v_cmd.head<2>() *= gains_.max_speed_xy / vxy;
  v_cmd.z() = std::clamp(v_cmd.z(), -gains_.max_speed_z, gains_.max_speed_z);

  // Velocity loop: PI on velocity plus the reference acceleration.
  Eigen::Vector3d a_cmd = ref.acceleration;
  for (int i = 0; i < 3; ++i) {
    const double e = v_cmd[i] - s.velocity[i];
    a_cmd[i] += vel_pid_[i].update(e, 0.0, dt, accel_saturated_[i]);
  }

  // Thrust vector F = m (a + g e3), its tilt limited by shrinking the horizontal part
  // (altitude authority is kept before horizontal acceleration).
  Eigen::Vector3d F = params_.mass * (a_cmd + g * e3);
  F.z() = std::max(F.z(), 0.1 * params_.mass * g);
  const double max_h = F.z() * std::tan(gains_.max_tilt_deg * M_PI / 180.0);
  const double h = F.head<2>().norm();
  for (int i = 0; i < 3; ++i) accel_saturated_[i] = 0;
  if (h > max_h) {
    F.head<2>() *= max_h / h;
    for (int i = 0; i < 2; ++i) accel_saturated_[i] = (a_cmd[i] > 0) ? 1 : -1;
  }

  // Desired attitude: body z along F, heading from the reference yaw.
  const Eigen::Vector3d b3d = F.normalized();
  const Eigen::Vector3d b1c(std::cos(ref.yaw), std::sin(ref.yaw), 0.0);
  const Eigen::Vector3d b2d = b3d.cross(b1c).normalized();
  const Eigen::Vector3d b1d = b2d.cross(b3d);
  Eigen::Matrix3d Rd;
  Rd << b1d, b2d, b3d;
  desired_rpy_ = {std::atan2(Rd(2, 1), Rd(2, 2)), -std::asin(std::clamp(Rd(2, 0), -1.0, 1.0)),
                  std::atan2(Rd(1, 0), Rd(0, 0))};

  // Collective thrust: the part of F along the current body z axis.
  const Eigen::Matrix3d R = s.attitude.toRotationMatrix();
  const double thrust = std::max(0.0, F.dot(R.col(2)));

  // Attitude loop on the quaternion error q_e = q^-1 q_d (valid for large errors, unlike Euler
  // differences): body rate command = 2 K sign(w_e) vec(q_e).
  Eigen::Quaterniond qd(Rd);
  Eigen::Quaterniond qe = s.attitude.conjugate() * qd;
  if (qe.w() < 0) qe.coeffs() *= -1.0;
  Eigen::Vector3d rate_cmd = 2.0 * gains_.att_kp.cwiseProduct(qe.vec());
  // Feed-forward of the reference yaw rate, expressed in the body frame.
  rate_cmd += R.transpose() * (ref.yaw_rate * e3);
  for (int i = 0; i < 2; ++i)
    rate_cmd[i] = std::clamp(rate_cmd[i], -gains_.max_rate, gains_.max_rate);

  // Rate loop: PI on body rates -> angular acceleration; torque = J alpha + w x J w.
  Eigen::Vector3d alpha;
  for (int i = 0; i < 3; ++i)
    alpha[i] =
        rate_pid_[i].update(rate_cmd[i] - s.angular_velocity[i], 0.0, dt, rate_saturated_[i]);
  const Eigen::Vector3d J = params_.inertia;
  const Eigen::Vector3d Jw = J.cwiseProduct(s.angular_velocity);
  const Eigen::Vector3d torque = J.cwiseProduct(alpha) + s.angular_velocity.cross(Jw);

  ControlOutput out;
  out.collective_thrust = thrust;
  out.torque = torque;
  out.rotor_thrusts = mixer_.allocateLimited(thrust, torque, &out.saturated);
  // Freeze rate integrators while the mixer could not deliver the torque.
  const Eigen::Vector4d delivered = mixer_.wrench(out.rotor_thrusts);
  for (int i = 0; i < 3; ++i) {
    const double shortfall = torque[i] - delivered[i + 1];
    rate_saturated_[i] = std::abs(shortfall) > 1e-9 ? (shortfall > 0 ? 1 : -1) : 0;
  }
  return out;
}

namespace {

// Roll and pitch share one gain (the airframe is symmetric); yaw has its own.
const GainTable<CascadeGains>& cascadeGains() {
  using G = CascadeGains;
  static const GainTable<G> table =
      GainTable<G>()
          .gain("pos_kp", &G::pos_kp, 0.0, 100.0, "position error -> velocity command, 1/s")
          .gain("vel_kp", &G::vel_kp, 0.0, 100.0, "velocity error -> acceleration command, 1/s")
          .gain("vel_ki", &G::vel_ki, 0.0, 100.0, "integral of the velocity error, 1/s^2")
          .gain("vel_i_limit", &G::vel_i_limit, 0.0, 100.0,
                "bound on the velocity integral's contribution, m/s^2")
          .gain("max_speed_xy", &G::max_speed_xy, 0.01, 100.0,
                "horizontal velocity command limit, m/s")
          .gain("max_speed_z", &G::max_speed_z, 0.01, 100.0, "vertical velocity command limit, m/s")
          .gain("max_tilt_deg", &G::max_tilt_deg, 1.0, 89.0,
                "limit on the thrust vector's angle from vertical, deg")
          .rollPitchAndYaw("att_kp", &G::att_kp, 1e4, "attitude error -> body rate command, 1/s")
          .rollPitchAndYaw("rate_kp", &G::rate_kp, 1e4, "rate error -> angular acceleration, 1/s")
          .rollPitchAndYaw("rate_ki", &G::rate_ki, 1e4, "integral of the rate error, 1/s^2")
          .rollPitchAndYaw("rate_i_limit", &G::rate_i_limit, 1e4,
                           "bound on the rate integral's contribution, rad/s^2")
          .gain("max_rate", &G::max_rate, 0.1, 100.0, "roll and pitch rate command limit, rad/s");
  return table;
}

}  // namespace

void registerCascadeController(ControllerRegistry& registry) {
  ControllerEntry e;
  e.name = CascadeController::kName;
  e.summary =
      "Navratil 2019's cascade (Quan 2017): position P -> velocity PI -> attitude P -> rate PI";
  e.gains = cascadeGains().declarations();
  e.team_shortfall = 0.62;  // swarm32 0.88 (a 0.2 m sag under another), dense 1.09
  e.make = [](const QuadrotorParams& params, ParamSet& gains,
              const ControllerOptions&) -> std::unique_ptr<FlightController> {
    return std::make_unique<CascadeController>(params, cascadeGains().read(gains));
  };
  registry.add(std::move(e));
}

}  // namespace cosim
