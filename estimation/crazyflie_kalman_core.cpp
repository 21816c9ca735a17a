#include "estimation/crazyflie_kalman_core.h"

#include <cmath>
#include <stdexcept>

#include "estimation/rotation_vector.h"

namespace cosim {
namespace {

// kalman_core.c: "The bounds on the covariance, these shouldn't be hit, but sometimes are".
constexpr double kMaxCovariance = 100.0;  // MAX_COVARIANCE
constexpr double kMinCovariance = 1e-6;   // MIN_COVARIANCE, on the diagonal only
// finalize folds the attitude error into q only if some component exceeds 0.1e-3 rad and none
// reaches 10 rad (kalmanCoreFinalize); a smaller error is dropped with the reset.
constexpr double kMinFoldedError = 0.1e-3;
constexpr double kMaxFoldedError = 10.0;

Eigen::Matrix3d crossProductMatrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return S;
}

// The covariance rotation of an attitude error d (Rodrigues parameters, |d| = tan(angle / 2)),
// to second order: exps(-d) ~ I - [d]x + [d]x^2 / 2 (Mueller, Hehn, D'Andrea 2016; the matrix
// of kalmanCoreFinalize and of predictDt's attitude block), with [d]x^2 = d d^T - |d|^2 I.
Eigen::Matrix3d attitudeErrorRotation(const Eigen::Vector3d& d) {
  const Eigen::Matrix3d S = crossProductMatrix(d);
  return Eigen::Matrix3d::Identity() - S + 0.5 * S * S;
}

}  // namespace

CrazyflieKalmanCore::CrazyflieKalmanCore(const CrazyflieKalmanParams& params) : params_(params) {
  init();
}

void CrazyflieKalmanCore::init() {
  S_.setZero();
  S_.segment<3>(kPosition) = params_.initial_position;
  initial_q_ = Eigen::Quaterniond(Eigen::AngleAxisd(params_.initial_yaw, Eigen::Vector3d::UnitZ()));
  q_ = initial_q_;
  // The firmware starts R at the identity whatever the yaw ("this only affects the first
  // prediction step"); the first finalize makes it R(q).
  R_.setIdentity();
  P_.setZero();
  const CrazyflieKalmanParams& p = params_;
  const double sd[kDim] = {p.std_initial_position_xy,        p.std_initial_position_xy,
                           p.std_initial_position_z,         p.std_initial_velocity,
                           p.std_initial_velocity,           p.std_initial_velocity,
                           p.std_initial_attitude_rollpitch, p.std_initial_attitude_rollpitch,
                           p.std_initial_attitude_yaw};
  for (int i = 0; i < kDim; ++i) P_(i, i) = sd[i] * sd[i];
  updated_ = false;
  bounded_ = false;
}

void CrazyflieKalmanCore::setState(const Eigen::Vector3d& position,
                                   const Eigen::Vector3d& body_velocity,
                                   const Eigen::Quaterniond& attitude) {
  S_.segment<3>(kPosition) = position;
  S_.segment<3>(kVelocity) = body_velocity;
  S_.segment<3>(kAttitude).setZero();
  q_ = attitude.normalized();
  R_ = q_.toRotationMatrix();
}

void CrazyflieKalmanCore::predict(const Eigen::Vector3d& accel, const Eigen::Vector3d& gyro,
                                  double dt, bool flying) {
  const double g = params_.gravity;
  const Eigen::Vector3d p = S_.segment<3>(kVelocity);
  const Eigen::Vector3d up_in_body = R_.row(2).transpose();  // R^T e3

  // Linearised dynamics, forward Euler over dt (predictDt's A; d = 0 at the start of a step):
  //   dx/dp = R dt,  dx/dd = -R [p]x dt            (x' = R (I + [d]x) p)
  //   dp/dp = I - [omega]x dt (- dragB dt flying),  dp/dd = -g [R^T e3]x dt
  //                                                 (p' = ... - g (I - [d]x) R^T e3)
  //   dd/dd = the rotation of the error by the step's turn, Rodrigues parameters omega dt / 2.
  // P <- A P A^T block by block (A is the identity but for these five blocks: 810 multiply-adds
  // against 1458 for two dense products), rows first (M = A P), then columns (M A^T); each pass
  // overwrites a block only after every block that reads it.
  const Eigen::Matrix3d Apv = R_ * dt;
  const Eigen::Matrix3d Apa = -R_ * crossProductMatrix(p) * dt;
  Eigen::Matrix3d Avv = Eigen::Matrix3d::Identity() - crossProductMatrix(gyro) * dt;
  if (flying) Avv.diagonal() -= params_.drag_b * dt;
  const Eigen::Matrix3d Ava = -g * crossProductMatrix(up_in_body) * dt;
  const Eigen::Matrix3d Aaa = attitudeErrorRotation(0.5 * dt * gyro);
  using Rows = Eigen::Matrix<double, 3, kDim>;
  using Cols = Eigen::Matrix<double, kDim, 3>;
  P_.middleRows<3>(kPosition) +=
      Apv.lazyProduct(P_.middleRows<3>(kVelocity)) + Apa.lazyProduct(P_.middleRows<3>(kAttitude));
  const Rows v_rows =
      Avv.lazyProduct(P_.middleRows<3>(kVelocity)) + Ava.lazyProduct(P_.middleRows<3>(kAttitude));
  P_.middleRows<3>(kVelocity) = v_rows;
  const Rows a_rows = Aaa.lazyProduct(P_.middleRows<3>(kAttitude));
  P_.middleRows<3>(kAttitude) = a_rows;
  P_.middleCols<3>(kPosition) += P_.middleCols<3>(kVelocity).lazyProduct(Apv.transpose()) +
                                 P_.middleCols<3>(kAttitude).lazyProduct(Apa.transpose());
  const Cols v_cols = P_.middleCols<3>(kVelocity).lazyProduct(Avv.transpose()) +
                      P_.middleCols<3>(kAttitude).lazyProduct(Ava.transpose());
  P_.middleCols<3>(kVelocity) = v_cols;
  const Cols a_cols = P_.middleCols<3>(kAttitude).lazyProduct(Aaa.transpose());
  P_.middleCols<3>(kAttitude) = a_cols;
  bounded_ = false;
  // (The process noise is added by the caller, at its own cadence: addProcessNoise.)

  // The state. Flying, only the body z specific force is taken from the accelerometer.
  const double dt2 = dt * dt;
  Eigen::Vector3d a = accel;
  if (flying) a.head<2>().setZero();
  const Eigen::Vector3d dx_body = p * dt + 0.5 * dt2 * a;
  S_.segment<3>(kPosition) += R_ * dx_body;
  S_(kPosition + 2) -= 0.5 * g * dt2;
  Eigen::Vector3d dp = a - gyro.cross(p) - g * up_in_body;  // the Coriolis term: body velocity
  if (flying) {
    // The drag of the velocity at the centre of pressure, p + omega x cop (zero without drag).
    const Eigen::Vector3d v_cop = p + gyro.cross(params_.center_of_pressure);
    dp -= params_.drag_b.cwiseProduct(v_cop);
  }
  S_.segment<3>(kVelocity) += dt * dp;

  // The attitude turned by the gyroscope over dt, in the body frame: q <- q (x) Exp(omega dt).
  // (The firmware adds 1e-6 rad to the angle it divides by; the exact map differs from it by
  // less than that.)
  Eigen::Quaterniond q = q_ * quaternionFromRotationVector(dt * gyro);
  if (!flying) {
    // On the ground the attitude creeps back to the initial one (the roll/pitch zero reversion).
    const double r = params_.attitude_reversion;
    q.coeffs() = (1.0 - r) * q.coeffs() + r * initial_q_.coeffs();
  }
  q_ = q.normalized();
  updated_ = true;
}

void CrazyflieKalmanCore::addProcessNoise(double dt) {
  if (!(dt > 0.0)) return;
  const CrazyflieKalmanParams& p = params_;
  // addProcessNoiseDt: standard deviations that add up linearly over the step, squared.
  const double pos_xy = p.proc_noise_acc_xy * dt * dt + p.proc_noise_vel * dt + p.proc_noise_pos;
  const double pos_z = p.proc_noise_acc_z * dt * dt + p.proc_noise_vel * dt + p.proc_noise_pos;
  const double vel_xy = p.proc_noise_acc_xy * dt + p.proc_noise_vel;
  const double vel_z = p.proc_noise_acc_z * dt + p.proc_noise_vel;
  const double att_rp = p.meas_noise_gyro_rollpitch * dt + p.proc_noise_att;
  const double att_yaw = p.meas_noise_gyro_yaw * dt + p.proc_noise_att;
  const double add[kDim] = {pos_xy, pos_xy, pos_z, vel_xy, vel_xy, vel_z, att_rp, att_rp, att_yaw};
  for (int i = 0; i < kDim; ++i) P_(i, i) += add[i] * add[i];
  if (bounded_) {
    for (int i = 0; i < kDim; ++i) P_(i, i) = bounded(P_(i, i), true);
  } else {
    boundCovariance();
  }
}

void CrazyflieKalmanCore::updatePosition(const Eigen::Vector3d& position, double std) {
  for (int i = 0; i < 3; ++i) scalarUpdate(kPosition + i, position[i] - S_(kPosition + i), std);
}

void CrazyflieKalmanCore::updateAttitude(const Eigen::Quaterniond& attitude, double std) {
  // The residual rotation in the body frame, q_est^-1 (x) q_meas, as small angles 2 v / w
  // (mm_pose.c, after Trawny and Roumeliotis 2005, eq. 141). The rig's 2024 fork computes it so;
  // bitcraze's firmware changed it in September 2025 to q_meas (x) q_est^-1, a world-frame
  // residual, which disagrees with the body-frame error the filter folds in (q (x) dq).
  const Eigen::Quaterniond r = q_.conjugate() * attitude.normalized();
  const Eigen::Vector3d error = (2.0 / r.w()) * r.vec();
  // Three scalar updates, each with its component of the one residual, as the firmware: the
  // attitude error an earlier update of the same pose has left is not subtracted.
  for (int i = 0; i < 3; ++i) scalarUpdate(kAttitude + i, error[i], std);
}

void CrazyflieKalmanCore::scalarUpdate(int index, double error, double std) {
  if (!(std > 0.0)) throw std::invalid_argument("CrazyflieKalmanCore: std must be positive");
  const double r = std * std;
  const StateVector ph = P_.col(index);  // P H^T
  const double s = ph[index] + r;        // H P H^T + R
  const StateVector k = ph / s;
  S_ += k * error;
  // Joseph form, (I - K H) P (I - K H)^T + K R K^T, expanded for H = e_index:
  // P_jk - K_j P_ik - P_ji K_k + K_j K_k (P_ii + R), symmetric as computed, each entry then
  // bounded (the firmware's pass after the product, folded into it).
  for (int j = 0; j < kDim; ++j) {
    for (int c = j; c < kDim; ++c) {
      const double v = bounded(P_(j, c) - k[j] * ph[c] - ph[j] * k[c] + k[j] * k[c] * s, j == c);
      P_(j, c) = v;
      P_(c, j) = v;
    }
  }
  bounded_ = true;
  updated_ = true;
}

bool CrazyflieKalmanCore::finalize() {
  if (!updated_) return false;
  const Eigen::Vector3d v = S_.segment<3>(kAttitude);
  const double largest = v.cwiseAbs().maxCoeff();
  if (largest > kMinFoldedError && largest < kMaxFoldedError) {
    q_ = (q_ * quaternionFromRotationVector(v)).normalized();
    // Rotate the covariance with the body: the attitude rows by G, the columns by G^T, G the
    // rotation of an error d = v / 2 (first order in tan(|v| / 2) v / |v|, as the firmware).
    const Eigen::Matrix3d G = attitudeErrorRotation(0.5 * v);
    const Eigen::Matrix<double, 3, kDim> rows = G * P_.middleRows<3>(kAttitude);
    P_.middleRows<3>(kAttitude) = rows;
    P_.middleCols<3>(kAttitude) = rows.transpose();
    P_.block<3, 3>(kAttitude, kAttitude) = rows.middleCols<3>(kAttitude) * G.transpose();
    bounded_ = false;
  }
  R_ = q_.toRotationMatrix();
  S_.segment<3>(kAttitude).setZero();
  if (!bounded_) boundCovariance();
  updated_ = false;
  return true;
}

bool CrazyflieKalmanCore::withinBounds() const {
  for (int i = 0; i < 3; ++i) {
    if (params_.max_position > 0.0 && std::abs(S_(kPosition + i)) > params_.max_position)
      return false;
    if (params_.max_velocity > 0.0 && std::abs(S_(kVelocity + i)) > params_.max_velocity)
      return false;
  }
  // A NaN compares false above: the firmware would go on with it; the reset is what it needs.
  return S_.allFinite();
}

double CrazyflieKalmanCore::bounded(double v, bool diagonal) {
  if (std::isnan(v) || v > kMaxCovariance) return kMaxCovariance;
  if (diagonal && v < kMinCovariance) return kMinCovariance;
  return v;
}

void CrazyflieKalmanCore::boundCovariance() {
  for (int j = 0; j < kDim; ++j) {
    for (int i = j; i < kDim; ++i) {
      const double v = bounded(0.5 * (P_(i, j) + P_(j, i)), i == j);
      P_(i, j) = v;
      P_(j, i) = v;
    }
  }
  bounded_ = true;
}

}  // namespace cosim
