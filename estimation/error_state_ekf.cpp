#include "estimation/error_state_ekf.h"

#include <stdexcept>

#include "estimation/rotation_vector.h"

namespace cosim {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return S;
}

// P = (P + P^T) / 2 element by element (the expression form would read what it has written).
void symmetrise(ErrorStateEkf::Covariance& P) {
  for (int i = 0; i < ErrorStateEkf::kDim; ++i) {
    for (int j = i + 1; j < ErrorStateEkf::kDim; ++j) {
      const double m = 0.5 * (P(i, j) + P(j, i));
      P(i, j) = m;
      P(j, i) = m;
    }
  }
}

}  // namespace

ErrorStateEkf::ErrorStateEkf(const ImuNoise& noise, double gravity)
    : noise_(noise), gravity_(gravity) {}

void ErrorStateEkf::initialise(const NavigationState& x, const Covariance& P0) {
  x_ = x;
  x_.attitude.normalize();
  P_ = P0;
  symmetrise(P_);
  last_imu_ = ImuMeasurement{};
  has_imu_ = false;
}

Eigen::Vector3d ErrorStateEkf::angularVelocity() const {
  return has_imu_ ? Eigen::Vector3d(last_imu_.gyro - x_.gyro_bias) : Eigen::Vector3d::Zero();
}

Eigen::Vector3d ErrorStateEkf::specificForce() const {
  return has_imu_ ? Eigen::Vector3d(last_imu_.accel - x_.accel_bias) : Eigen::Vector3d::Zero();
}

void ErrorStateEkf::predictTo(double t, const ImuMeasurement& imu) {
  const double dt = t - x_.t;
  if (!(dt >= 0.0)) throw std::invalid_argument("ErrorStateEkf: cannot predict backwards in time");
  last_imu_ = imu;
  has_imu_ = true;
  if (dt == 0.0) return;

  // Nominal state (Sec. 5.4.1, eq. 260), the biases constant, except that the specific force is
  // rotated into the world by the attitude at the interval's midpoint rather than its start (the
  // midpoint rule, Solà's Appendix A.2 applied to eq. 260): over a 10 ms prediction a vehicle
  // turning at 1 rad/s turns 0.6 deg, and rotating by the start attitude would err by half of
  // that on the velocity increment, systematically (a first-order error the process noise does
  // not cover); the midpoint makes it second order.
  const Eigen::Vector3d a = imu.accel - x_.accel_bias;  // specific force, body
  const Eigen::Vector3d w = imu.gyro - x_.gyro_bias;    // angular velocity, body
  const Eigen::Matrix3d R = x_.attitude.toRotationMatrix();
  const Eigen::Matrix3d R_mid =
      (x_.attitude * quaternionFromRotationVector(0.5 * dt * w)).toRotationMatrix();
  const Eigen::Vector3d acc = R_mid * a - Eigen::Vector3d(0.0, 0.0, gravity_);
  const Eigen::Quaterniond dq = quaternionFromRotationVector(w * dt);
  x_.position += x_.velocity * dt + 0.5 * dt * dt * acc;
  x_.velocity += acc * dt;
  x_.attitude = (x_.attitude * dq).normalized();
  x_.t = t;

  propagateCovariance(R, a, dq.toRotationMatrix(), dt);
}

// P <- F_x P F_x^T + F_i Q_i F_i^T (eq. 264) with, in 3 x 3 blocks (eq. 269, R the attitude at
// the start of the step, a the bias-corrected specific force, dR = R{w dt}):
//   F_x = [ I  I dt  0           0      0
//           0  I    -R [a]x dt  -R dt   0
//           0  0     dR^T        0     -I dt
//           0  0     0           I      0
//           0  0     0           0      I ]
// F P is formed row block by row block in place (each reads only blocks not yet overwritten),
// then (F P) F^T column block by column block; row blocks 3 and 4 of F are the identity.
void ErrorStateEkf::propagateCovariance(const Eigen::Matrix3d& R, const Eigen::Vector3d& a,
                                        const Eigen::Matrix3d& dR, double dt) {
  const Eigen::Matrix3d A = skew(a);
  const Eigen::Matrix3d dRt = dR.transpose();
  const Eigen::Matrix3d Rdt = R * dt;

  // Rows: M = F P.
  P_.middleRows<3>(kPosition) += dt * P_.middleRows<3>(kVelocity);
  const Eigen::Matrix<double, 3, kDim> v_row =
      A.lazyProduct(P_.middleRows<3>(kAttitude)) + P_.middleRows<3>(kAccelBias);
  P_.middleRows<3>(kVelocity) -= Rdt.lazyProduct(v_row);
  const Eigen::Matrix<double, 3, kDim> theta_row =
      dRt.lazyProduct(P_.middleRows<3>(kAttitude)) - dt * P_.middleRows<3>(kGyroBias);
  P_.middleRows<3>(kAttitude) = theta_row;

  // Columns: M F^T ([a]x^T = -[a]x), for the top 9 rows only. F^T leaves columns 9-14 alone,
  // so the bottom rows' columns 0-8 are by symmetry the transpose of the top rows' columns 9-14,
  // which the row pass already produced; copying them makes P exactly symmetric there.
  constexpr int kTop = 9;
  auto top = P_.topRows<kTop>();
  top.middleCols<3>(kPosition) += dt * top.middleCols<3>(kVelocity);
  const Eigen::Matrix<double, kTop, 3> v_col =
      top.middleCols<3>(kAccelBias) - top.middleCols<3>(kAttitude).lazyProduct(A);
  top.middleCols<3>(kVelocity) -= v_col.lazyProduct(Rdt.transpose());
  const Eigen::Matrix<double, kTop, 3> theta_col =
      top.middleCols<3>(kAttitude).lazyProduct(dR) - dt * top.middleCols<3>(kGyroBias);
  top.middleCols<3>(kAttitude) = theta_col;
  P_.bottomLeftCorner<kDim - kTop, kTop>() = P_.topRightCorner<kTop, kDim - kTop>().transpose();

  // F_i Q_i F_i^T (eq. 270): white noise on velocity and angle, random walk on the biases.
  const double v_var = noise_.accel_noise * noise_.accel_noise * dt;
  const double theta_var = noise_.gyro_noise * noise_.gyro_noise * dt;
  const double ab_var = noise_.accel_bias_walk * noise_.accel_bias_walk * dt;
  const double wb_var = noise_.gyro_bias_walk * noise_.gyro_bias_walk * dt;
  for (int i = 0; i < 3; ++i) {
    P_(kVelocity + i, kVelocity + i) += v_var;
    P_(kAttitude + i, kAttitude + i) += theta_var;
    P_(kAccelBias + i, kAccelBias + i) += ab_var;
    P_(kGyroBias + i, kGyroBias + i) += wb_var;
  }
  // The top-left 9 x 9 block went through both passes: equal across the diagonal only up to
  // rounding.
  for (int i = 0; i < kTop; ++i) {
    for (int j = i + 1; j < kTop; ++j) {
      const double m = 0.5 * (P_(i, j) + P_(j, i));
      P_(i, j) = m;
      P_(j, i) = m;
    }
  }
}

void ErrorStateEkf::updatePosition(const PositionMeasurement& z) {
  updateBlock(kPosition, z.position - x_.position, z.sigma);
}

void ErrorStateEkf::updateAttitude(const AttitudeMeasurement& z) {
  updateBlock(kAttitude, rotationVectorFromQuaternion(x_.attitude.conjugate() * z.attitude),
              z.sigma);
}

void ErrorStateEkf::updateBlock(int block, const Eigen::Vector3d& r, double sigma) {
  if (!(sigma > 0.0)) throw std::invalid_argument("ErrorStateEkf: fix sigma must be positive");
  const double var = sigma * sigma;

  // Gain (Sec. 6.1): K = P H^T (H P H^T + V)^-1, with P H^T the block's columns of P.
  const Eigen::Matrix<double, kDim, 3> PHt = P_.middleCols<3>(block);
  const Eigen::Matrix3d S = PHt.middleRows<3>(block) + var * Eigen::Matrix3d::Identity();
  const Eigen::Matrix<double, kDim, 3> K = PHt.lazyProduct(S.inverse());
  const Eigen::Matrix<double, kDim, 1> dx = K * r;

  // Joseph form, P <- (I - K H) P (I - K H)^T + K V K^T: symmetric and positive semi-definite
  // by construction, unlike (I - K H) P when K is not exactly optimal in floating point.
  // Expanded with H selecting a block (H P = rows of P, H P H^T + V = S), it is
  // P - K (P H^T)^T - (P H^T) K^T + K S K^T = P - (K W^T + W K^T) with W = P H^T - K S / 2: a
  // symmetric rank-6 update, done on the lower triangle and mirrored.
  // (Transposed, so that each entry's two dot products read contiguous columns.)
  const Eigen::Matrix<double, 3, kDim> Kt = K.transpose();
  const Eigen::Matrix<double, 3, kDim> Wt = (PHt - 0.5 * K.lazyProduct(S)).transpose();
  for (int j = 0; j < kDim; ++j) {
    for (int i = j; i < kDim; ++i) {
      const double v = P_(i, j) - Kt.col(i).dot(Wt.col(j)) - Wt.col(i).dot(Kt.col(j));
      P_(i, j) = v;
      P_(j, i) = v;
    }
  }

  // Injection (Sec. 6.2): x <- x (+) dx, the attitude error on the right (local).
  x_.position += dx.segment<3>(kPosition);
  x_.velocity += dx.segment<3>(kVelocity);
  const Eigen::Vector3d dtheta = dx.segment<3>(kAttitude);
  x_.attitude = (x_.attitude * quaternionFromRotationVector(dtheta)).normalized();
  x_.accel_bias += dx.segment<3>(kAccelBias);
  x_.gyro_bias += dx.segment<3>(kGyroBias);

  // Reset (Sec. 6.3): the error now has zero mean about the new nominal state; its covariance
  // is P <- G P G^T with G = I except G_theta = I - [dtheta / 2]x on the attitude block: the
  // attitude rows become G times themselves, the columns their transpose (P stays exactly
  // symmetric), and the attitude block G P_theta G^T.
  const Eigen::Matrix3d G = Eigen::Matrix3d::Identity() - skew(0.5 * dtheta);
  const Eigen::Matrix<double, 3, kDim> rows = G.lazyProduct(P_.middleRows<3>(kAttitude));
  P_.middleRows<3>(kAttitude) = rows;
  P_.middleCols<3>(kAttitude) = rows.transpose();
  const Eigen::Matrix3d block_theta = rows.middleCols<3>(kAttitude).lazyProduct(G.transpose());
  P_.block<3, 3>(kAttitude, kAttitude) = 0.5 * (block_theta + block_theta.transpose());
}

}  // namespace cosim
