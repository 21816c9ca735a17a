#include "control/geometric_controller.h"

#include <algorithm>
#include <cmath>

#include "control/controller_registry.h"
#include "control/thrust_direction.h"
#include "control/vee_map.h"

namespace cosim {

GeometricController::GeometricController(const QuadrotorParams& params, const GeometricGains& gains,
                                         bool drag_compensation)
    : params_(params),
      gains_(gains),
      D_(drag_compensation ? params.linearDragPerMass() : Eigen::Vector3d::Zero()),
      mixer_(params) {}

void GeometricController::reset() {
  integral_.setZero();
  saturated_ = false;
  R_d_.setIdentity();
  omega_d_.setZero();
}

ControlOutput GeometricController::update(const VehicleState& s, const FlatReference& ref,
                                          double dt) {
  const Eigen::Vector3d e3 = Eigen::Vector3d::UnitZ();
  const double g = params_.gravity;
  const Eigen::Vector3d J = params_.inertia;

  // Translational errors (Lee et al. eq. 6) and the integral, which runs only near a steady
  // state and while the mixer delivers what is asked (conditional integration against windup).
  const Eigen::Vector3d e_x = s.position - ref.position;
  const Eigen::Vector3d e_v = s.velocity - ref.velocity;
  if (!saturated_ && gains_.k_i > 0.0 && e_v.norm() < gains_.i_velocity_zone) {
    integral_ += e_x * dt;
    const double bound = gains_.i_limit / gains_.k_i;
    integral_ = integral_.cwiseMax(-bound).cwiseMin(bound);
  }

  // Desired thrust per unit mass, eq. 15 with z up: A = -k_x e_x - k_v e_v - k_i int e_x + g e3
  // + a_d, plus the rotor drag R D R^T v_d with drag compensation (Faessler et al.; zero D
  // otherwise). Its tilt is limited by shrinking the horizontal part (height is kept first).
  const Eigen::Matrix3d R = s.attitude.toRotationMatrix();
  const Eigen::Matrix3d D = D_.asDiagonal();
  const Eigen::Vector3d A = limitTilt(-gains_.k_x.cwiseProduct(e_x) - gains_.k_v.cwiseProduct(e_v) -
                                          gains_.k_i * integral_ + g * e3 + ref.acceleration +
                                          R * D * R.transpose() * ref.velocity,
                                      0.1 * g, gains_.max_tilt_deg);

  // Desired attitude: b3 along A, b1 as close to the reference heading as b3 allows.
  R_d_ = attitudeAlong(A, ref.yaw);
  const Eigen::Vector3d b1d = R_d_.col(0), b2d = R_d_.col(1), b3d = R_d_.col(2);

  // Desired body rates from the jerk (Mellinger and Kumar eq. 7): the change of the thrust
  // direction is the jerk's part normal to b3, divided by the thrust per unit mass. With drag
  // (Faessler et al.) the jerk is j + R_d D R_d^T a_d and the thrust c + (d - d_z) b3 . v_d
  // (floored at c / 2, as IndiController::feedForward does).
  const Eigen::Vector3d j_D = ref.jerk + R_d_ * D * R_d_.transpose() * ref.acceleration;
  const double c = A.norm();
  const double b3_v = b3d.dot(ref.velocity);
  omega_d_ = {-j_D.dot(b2d) / std::max(c + (D_.y() - D_.z()) * b3_v, 0.5 * c),
              j_D.dot(b1d) / std::max(c + (D_.x() - D_.z()) * b3_v, 0.5 * c),
              ref.yaw_rate * b3d.z()};

  // Attitude errors on SO(3) (eqs. 10-11) and the moment (eq. 16); the desired angular
  // acceleration is taken as zero (it would need the reference snap).
  const Eigen::Vector3d e_R = 0.5 * vee(R_d_.transpose() * R - R.transpose() * R_d_);
  const Eigen::Vector3d omega_d_body = R.transpose() * R_d_ * omega_d_;
  const Eigen::Vector3d& w = s.angular_velocity;
  const Eigen::Vector3d e_w = w - omega_d_body;
  const Eigen::Vector3d alpha =
      -gains_.k_R.cwiseProduct(e_R) - gains_.k_omega.cwiseProduct(e_w) - w.cross(omega_d_body);
  const Eigen::Vector3d torque = J.cwiseProduct(alpha) + w.cross(J.cwiseProduct(w));

  // Collective thrust: the desired force's component along the current body z axis.
  ControlOutput out;
  out.collective_thrust = std::max(0.0, params_.mass * A.dot(R.col(2)));
  out.torque = torque;
  out.rotor_thrusts = mixer_.allocateLimited(out.collective_thrust, torque, &out.saturated);
  saturated_ = out.saturated;
  return out;
}

namespace {

// Horizontal axes share one gain, as roll and pitch do; z and yaw have their own.
const GainTable<GeometricGains>& geometricGains() {
  using G = GeometricGains;
  static const GainTable<G> table =
      GainTable<G>()
          .horizontalAndZ("k_x", &G::k_x, 1e4, "position error -> acceleration, 1/s^2")
          .horizontalAndZ("k_v", &G::k_v, 1e4, "velocity error -> acceleration, 1/s")
          .gain("k_i", &G::k_i, 0.0, 1e4, "integral of the position error, 1/s^3")
          .gain("i_limit", &G::i_limit, 0.0, 100.0, "bound on the integral's contribution, m/s^2")
          .gain("i_velocity_zone", &G::i_velocity_zone, 0.0, 100.0,
                "the integral runs only while the velocity error is below this, m/s")
          .rollPitchAndYaw("k_R", &G::k_R, 1e4, "attitude error -> angular acceleration, 1/s^2")
          .rollPitchAndYaw("k_omega", &G::k_omega, 1e4,
                           "angular velocity error -> angular acceleration, 1/s")
          .gain("max_tilt_deg", &G::max_tilt_deg, 1.0, 89.0,
                "limit on the commanded thrust vector's tilt, deg");
  return table;
}

}  // namespace

void registerGeometricController(ControllerRegistry& registry) {
  ControllerEntry e;
  e.name = GeometricController::kName;
  e.summary = "Lee, Leok and McClamroch 2010 on SE(3), with the integral and rates from the jerk";
  e.gains = geometricGains().declarations();
  e.team_shortfall = 0.33;  // swarm32 1.17, dense 1.48
  e.compensates_drag = true;
  e.make = [](const QuadrotorParams& params, ParamSet& gains,
              const ControllerOptions& options) -> std::unique_ptr<FlightController> {
    return std::make_unique<GeometricController>(params, geometricGains().read(gains),
                                                 options.drag_compensation);
  };
  registry.add(std::move(e));
}

}  // namespace cosim
