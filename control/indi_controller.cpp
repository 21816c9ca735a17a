#include "control/indi_controller.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "control/controller_registry.h"
#include "control/thrust_direction.h"

namespace cosim {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& w) {
  Eigen::Matrix3d S;
  S << 0.0, -w.z(), w.y(), w.z(), 0.0, -w.x(), -w.y(), w.x(), 0.0;
  return S;
}

}  // namespace

IndiController::IndiController(const QuadrotorParams& params, const IndiGains& gains,
                               bool drag_compensation)
    : params_(params),
      gains_(gains),
      D_(drag_compensation ? params.linearDragPerMass() : Eigen::Vector3d::Zero()),
      mixer_(params),
      acceleration_filter_(gains.filter_cutoff_hz),
      thrust_filter_(gains.filter_cutoff_hz),
      gyro_filter_(gains.filter_cutoff_hz) {}

void IndiController::reset() {
  acceleration_filter_.clear();
  thrust_filter_.clear();
  gyro_filter_.clear();
  R_d_.setIdentity();
  omega_d_.setZero();
  omega_dot_d_.setZero();
}

// Differentiating dv/dt = c z_B - g e3 - R D R^T v (Faessler et al. 2018) once and projecting on
// x_B and y_B gives two rows of M omega = r; differentiating the heading constraint y_B . x_C = 0
// gives the third. Differentiating once more gives M omega_dot = E with the same M.
IndiController::FeedForward IndiController::feedForward(const Eigen::Matrix3d& R_d, double c,
                                                        const FlatReference& ref,
                                                        const Eigen::Vector3d& D) {
  FeedForward ff;
  const Eigen::Vector3d x_B = R_d.col(0), y_B = R_d.col(1), z_B = R_d.col(2);
  const Eigen::Vector3d x_C(std::cos(ref.yaw), std::sin(ref.yaw), 0.0);
  const Eigen::Vector3d y_C(-std::sin(ref.yaw), std::cos(ref.yaw), 0.0);
  const Eigen::Vector3d &v = ref.velocity, &a = ref.acceleration, &j = ref.jerk, &s = ref.snap;
  const double d_x = D.x(), d_y = D.y(), d_z = D.z();
  const double psi_dot = ref.yaw_rate, psi_ddot = ref.yaw_acceleration;

  // The thrust corrected by the drag along z_B . v: floored at c / 2, which it reaches only when
  // sinking along the body axis faster than c / (2 d) (13 m/s for the Iris in hover).
  const double B1 = std::max(c - (d_z - d_x) * z_B.dot(v), 0.5 * c);
  const double A2 = std::max(c + (d_y - d_z) * z_B.dot(v), 0.5 * c);
  Eigen::Matrix3d M;
  M << 0.0, B1, (d_y - d_x) * y_B.dot(v),  //
      A2, 0.0, (d_x - d_y) * x_B.dot(v),   //
      z_B.dot(x_C), 0.0, -x_B.dot(x_C);
  // det M = B1 (A2 x_B . x_C + C2 z_B . x_C): singular without thrust, or with the body x axis
  // perpendicular to the heading (the heading convention's own singularity).
  if (c < 1e-6 || std::abs(M.determinant()) < 1e-3 * B1 * A2) return ff;
  const Eigen::Matrix3d M_inv = M.inverse();

  // Body rates: the drag-corrected jerk j + D a along x_B and y_B; the heading row.
  const Eigen::Vector3d r(x_B.dot(j) + d_x * x_B.dot(a), -y_B.dot(j) - d_y * y_B.dot(a),
                          -psi_dot * y_B.dot(y_C));
  const Eigen::Vector3d w = M_inv * r;
  ff.omega = w;

  // Angular accelerations: the snap with its drag terms xi (the D j term and the rotation of
  // the drag by omega), the thrust rate c_dot, and the heading row differentiated again.
  const double c_dot = z_B.dot(j) + w.x() * (d_y - d_z) * y_B.dot(v) +
                       w.y() * (d_z - d_x) * x_B.dot(v) + d_z * z_B.dot(a);
  const Eigen::Matrix3d W = skew(w);
  const Eigen::Matrix3d Dm = D.asDiagonal();
  const Eigen::Vector3d xi =
      R_d * (W * W * Dm + Dm * W * W + 2.0 * W * Dm * W.transpose()) * R_d.transpose() * v +
      2.0 * R_d * (W * Dm + Dm * W.transpose()) * R_d.transpose() * a +
      R_d * Dm * R_d.transpose() * j;
  const Eigen::Vector3d E(
      x_B.dot(s) - 2.0 * c_dot * w.y() - c * w.x() * w.z() + x_B.dot(xi),
      -y_B.dot(s) - 2.0 * c_dot * w.x() + c * w.y() * w.z() - y_B.dot(xi),
      -(w.x() * w.y() * x_B.dot(x_C) + w.y() * w.z() * z_B.dot(x_C) +
        2.0 * psi_dot * (w.x() * z_B.dot(y_C) - w.z() * x_B.dot(y_C)) + psi_ddot * y_B.dot(y_C)));
  ff.omega_dot = M_inv * E;
  return ff;
}

ControlOutput IndiController::update(const VehicleState& s, const FlatReference& ref, double dt) {
  const Eigen::Vector3d e3 = Eigen::Vector3d::UnitZ();
  const double g = params_.gravity, m = params_.mass;
  const Eigen::Vector3d& J = params_.inertia;
  const Eigen::Matrix3d R = s.attitude.toRotationMatrix();

  // Filtered measurements: the acceleration (specific force in the world, plus gravity), the
  // rotor thrusts and the gyro with its derivative, all through the same filter.
  const Eigen::Vector3d a_f = acceleration_filter_.update(R * s.specific_force - g * e3, dt);
  const Eigen::Vector4d wrench_f = mixer_.wrench(thrust_filter_.update(s.rotor_thrusts, dt));
  gyro_filter_.update(s.angular_velocity, dt);
  const Eigen::Vector3d& Omega_dot_f = gyro_filter_.derivative();

  // Outer loop and the INDI increment of the specific thrust vector. The tilt of tau_c is
  // limited as in GeometricController (height is kept first).
  const Eigen::Vector3d a_c = gains_.k_x.cwiseProduct(ref.position - s.position) +
                              gains_.k_v.cwiseProduct(ref.velocity - s.velocity) + ref.acceleration;
  const Eigen::Vector3d tau_f = R.col(2) * wrench_f[0] / m;
  const Eigen::Vector3d tau_c = limitTilt(tau_f + a_c - a_f, 0.1 * g, gains_.max_tilt_deg);

  // Desired attitude: z along tau_c, x as close to the reference heading as z allows.
  R_d_ = attitudeAlong(tau_c, ref.yaw);

  // Flatness feed-forward at the commanded thrust, brought into the current body frame.
  const FeedForward ff = feedForward(R_d_, tau_c.norm(), ref, D_);
  omega_d_ = ff.omega;
  omega_dot_d_ = ff.omega_dot;
  const Eigen::Matrix3d R_e = R.transpose() * R_d_;
  const Eigen::Vector3d& Omega = s.angular_velocity;
  const Eigen::Vector3d Omega_ref = R_e * omega_d_;
  const Eigen::Vector3d Omega_dot_ref = R_e * omega_dot_d_ - Omega.cross(Omega_ref);

  // Attitude error from the error quaternion q_e = q^-1 q_d (the short way round).
  Eigen::Quaterniond q_e = s.attitude.conjugate() * Eigen::Quaterniond(R_d_);
  if (q_e.w() < 0.0) q_e.coeffs() *= -1.0;
  const Eigen::Vector3d xi_e = 2.0 * q_e.vec();
  const Eigen::Vector3d alpha_c = gains_.k_xi.cwiseProduct(xi_e) +
                                  gains_.k_omega.cwiseProduct(Omega_ref - Omega) + Omega_dot_ref;

  // INDI on the angular acceleration: the filtered torque plus the inertia times the increment.
  const Eigen::Vector3d mu_c = wrench_f.tail<3>() + J.cwiseProduct(alpha_c - Omega_dot_f);

  ControlOutput out;
  out.collective_thrust = std::max(0.0, m * tau_c.dot(R.col(2)));
  out.torque = mu_c;
  out.rotor_thrusts = mixer_.allocateLimited(out.collective_thrust, mu_c, &out.saturated);
  return out;
}

namespace {

// Horizontal axes share one gain, as roll and pitch do; z and yaw have their own.
const GainTable<IndiGains>& indiGains() {
  using G = IndiGains;
  static const GainTable<G> table =
      GainTable<G>()
          .horizontalAndZ("k_x", &G::k_x, 1e4, "position error -> acceleration, 1/s^2")
          .horizontalAndZ("k_v", &G::k_v, 1e4, "velocity error -> acceleration, 1/s")
          .rollPitchAndYaw("k_xi", &G::k_xi, 1e4, "attitude error -> angular acceleration, 1/s^2")
          .rollPitchAndYaw("k_omega", &G::k_omega, 1e4, "rate error -> angular acceleration, 1/s")
          .gain("filter_cutoff_hz", &G::filter_cutoff_hz, 0.1, 1e4,
                "cutoff of the low-pass every fed-back signal passes, Hz")
          .gain("max_tilt_deg", &G::max_tilt_deg, 1.0, 89.0,
                "limit on the commanded thrust vector's tilt, deg");
  return table;
}

}  // namespace

void registerIndiController(ControllerRegistry& registry) {
  ControllerEntry e;
  e.name = IndiController::kName;
  e.summary = "Tal and Karaman 2021: incremental nonlinear dynamic inversion with flatness";
  e.gains = indiGains().declarations();
  e.team_shortfall = 0.02;  // swarm32 1.48, dense 1.48
  e.compensates_drag = true;
  e.make = [](const QuadrotorParams& params, ParamSet& gains,
              const ControllerOptions& options) -> std::unique_ptr<FlightController> {
    return std::make_unique<IndiController>(params, indiGains().read(gains),
                                            options.drag_compensation);
  };
  registry.add(std::move(e));
}

}  // namespace cosim
