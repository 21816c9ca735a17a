#include "estimation/error_state_ekf.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>

#include "estimation/rotation_vector.h"

using namespace cosim;
using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using Covariance = ErrorStateEkf::Covariance;

namespace {

constexpr double kG = 9.81;
constexpr double kImuRate = 500.0;

// ADIS16448-class densities (sim/sensors/sensor_presets.cpp).
ImuNoise adisNoise() {
  ImuNoise n;
  n.gyro_noise = 3.3937e-4;
  n.gyro_bias_walk = 3.8785e-5;
  n.accel_noise = 4.0e-3;
  n.accel_bias_walk = 6.0e-3;
  return n;
}

Matrix3d skew(const Vector3d& v) {
  Matrix3d S;
  S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return S;
}

// A dense covariance with every block coupled, symmetric positive definite: A A^T + I/100 for a
// fixed A of entries in [-0.1, 0.1].
Covariance coupledCovariance() {
  Covariance A;
  for (int i = 0; i < 15; ++i)
    for (int j = 0; j < 15; ++j) A(i, j) = 0.1 * std::sin(1.7 * i + 0.3 * j * j + 0.5);
  return A * A.transpose() + 0.01 * Covariance::Identity();
}

Covariance diagonalCovariance(double p, double v, double theta, double ab, double wb) {
  Covariance P = Covariance::Zero();
  const double sd[5] = {p, v, theta, ab, wb};
  for (int b = 0; b < 5; ++b) P.block<3, 3>(3 * b, 3 * b) = sd[b] * sd[b] * Matrix3d::Identity();
  return P;
}

double angleBetween(const Quaterniond& a, const Quaterniond& b) {
  return rotationVectorFromQuaternion(a.conjugate() * b).norm();
}

}  // namespace

TEST(ErrorStateEkf, NoiseFreeImuIntegratesConstantAccelerationToTheParabola) {
  // A fixed tilted attitude and a constant world acceleration: the specific force is constant in
  // the body frame, and the nominal kinematics (p += v dt + a dt^2 / 2) are exact for it.
  NavigationState x0;
  x0.position = {1.0, -2.0, 3.0};
  x0.velocity = {0.5, 0.2, -0.1};
  x0.attitude = Quaterniond(Eigen::AngleAxisd(0.3, Vector3d(1, 2, 3).normalized()));
  const Vector3d a(0.8, -0.4, 0.3);
  ImuMeasurement imu;
  imu.accel = x0.attitude.conjugate() * (a + kG * Vector3d::UnitZ());

  ErrorStateEkf ekf(adisNoise(), kG);
  ekf.initialise(x0, Covariance::Identity());
  const int n = 1000;  // 2 s
  for (int k = 1; k <= n; ++k) {
    imu.t = k / kImuRate;
    ekf.predict(imu);
  }
  const double T = n / kImuRate;
  const NavigationState& x = ekf.state();
  EXPECT_DOUBLE_EQ(x.t, T);
  EXPECT_LT((x.position - (x0.position + x0.velocity * T + 0.5 * a * T * T)).norm(), 1e-9);
  EXPECT_LT((x.velocity - (x0.velocity + a * T)).norm(), 1e-10);
  EXPECT_LT(angleBetween(x.attitude, x0.attitude), 1e-12);
}

TEST(ErrorStateEkf, NoiseFreeImuIntegratesConstantBodyRateToTheExactRotation) {
  // Free fall (zero specific force) while spinning at a constant body rate: q(T) = q0 Exp(w T).
  NavigationState x0;
  x0.position = {0.0, 0.0, 50.0};
  x0.velocity = {1.0, 0.0, 2.0};
  x0.attitude = Quaterniond(Eigen::AngleAxisd(-0.7, Vector3d(0.2, 1.0, -0.4).normalized()));
  ImuMeasurement imu;
  imu.gyro = {0.3, -0.5, 0.8};

  ErrorStateEkf ekf(adisNoise(), kG);
  ekf.initialise(x0, Covariance::Identity());
  const int n = 1500;  // 3 s, 1.4 rad
  for (int k = 1; k <= n; ++k) {
    imu.t = k / kImuRate;
    ekf.predict(imu);
  }
  const double T = n / kImuRate;
  const Quaterniond expected = x0.attitude * quaternionFromRotationVector(imu.gyro * T);
  EXPECT_LT(angleBetween(ekf.state().attitude, expected), 1e-10);
  const Vector3d p = x0.position + x0.velocity * T - 0.5 * kG * T * T * Vector3d::UnitZ();
  EXPECT_LT((ekf.state().position - p).norm(), 1e-9);
}

TEST(ErrorStateEkf, BlockwiseCovariancePropagationEqualsTheDenseJacobianProduct) {
  // Solà eq. 264 with F_x of eq. 269 (no gravity state) and Q_i of eq. 270, written densely.
  NavigationState x0;
  x0.attitude = Quaterniond(Eigen::AngleAxisd(0.9, Vector3d(-1, 2, 0.5).normalized()));
  x0.accel_bias = {0.05, -0.1, 0.2};
  x0.gyro_bias = {0.01, 0.02, -0.03};
  const Covariance P0 = coupledCovariance();
  ImuMeasurement imu;
  imu.t = 0.004;  // two IMU periods: dt matters in every block
  imu.gyro = {0.4, -1.1, 0.7};
  imu.accel = {1.5, -0.8, 10.3};

  ErrorStateEkf ekf(adisNoise(), kG);
  ekf.initialise(x0, P0);
  ekf.predict(imu);

  const double dt = imu.t;
  const Matrix3d R = x0.attitude.toRotationMatrix();
  const Vector3d a = imu.accel - x0.accel_bias;
  const Vector3d w = imu.gyro - x0.gyro_bias;
  Covariance F = Covariance::Identity();
  F.block<3, 3>(0, 3) = dt * Matrix3d::Identity();
  F.block<3, 3>(3, 6) = -R * skew(a) * dt;
  F.block<3, 3>(3, 9) = -R * dt;
  F.block<3, 3>(6, 6) = quaternionFromRotationVector(w * dt).toRotationMatrix().transpose();
  F.block<3, 3>(6, 12) = -dt * Matrix3d::Identity();
  const ImuNoise n = adisNoise();
  Covariance Q = Covariance::Zero();
  Q.block<3, 3>(3, 3) = n.accel_noise * n.accel_noise * dt * Matrix3d::Identity();
  Q.block<3, 3>(6, 6) = n.gyro_noise * n.gyro_noise * dt * Matrix3d::Identity();
  Q.block<3, 3>(9, 9) = n.accel_bias_walk * n.accel_bias_walk * dt * Matrix3d::Identity();
  Q.block<3, 3>(12, 12) = n.gyro_bias_walk * n.gyro_bias_walk * dt * Matrix3d::Identity();
  const Covariance expected = F * P0 * F.transpose() + Q;

  EXPECT_LT((ekf.covariance() - expected).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_TRUE(ekf.covariance() == ekf.covariance().transpose());  // exactly symmetric
}

TEST(ErrorStateEkf, PositionFixPullsTheEstimateAndShrinksItsVarianceAsTheKalmanGainSays) {
  NavigationState x0;
  x0.position = {2.0, 1.0, 1.5};
  const double s0 = 0.1, s = 0.01;  // prior and fix standard deviations, m
  ErrorStateEkf ekf(adisNoise(), kG);
  ekf.initialise(x0, diagonalCovariance(s0, 0.2, 0.05, 0.1, 0.01));
  PositionMeasurement z;
  z.position = x0.position + Vector3d(0.05, -0.02, 0.1);
  z.sigma = s;
  ekf.updatePosition(z);

  // Scalar Kalman filter per axis: k = s0^2 / (s0^2 + s^2) = 0.990099, posterior variance
  // s0^2 s^2 / (s0^2 + s^2) = 9.90099e-5 m^2.
  const double k = s0 * s0 / (s0 * s0 + s * s);
  EXPECT_NEAR(k, 0.990099, 1e-6);
  EXPECT_LT((ekf.state().position - (x0.position + k * (z.position - x0.position))).norm(), 1e-15);
  for (int i = 0; i < 3; ++i) {
    // (1e-16: the update subtracts nearly all of a 1e-2 variance, so the last two of the 16
    // digits of the 1e-4 left are rounding.)
    EXPECT_NEAR(ekf.covariance()(i, i), s0 * s0 * s * s / (s0 * s0 + s * s), 1e-16);
    EXPECT_DOUBLE_EQ(ekf.covariance()(3 + i, 3 + i), 0.2 * 0.2);  // uncorrelated: untouched
  }
  EXPECT_LT(ekf.state().velocity.norm(), 1e-18);
}

TEST(ErrorStateEkf, UpdateEqualsTheDenseJosephFormFollowedByTheReset) {
  // With every state correlated to the position, a position fix corrects all of them:
  // dx = K r, P = (I - K H) P (I - K H)^T + K V K^T, then P = G P G^T (Solà Secs. 6.1-6.3).
  NavigationState x0;
  x0.position = {0.3, 0.1, 2.0};
  x0.attitude = Quaterniond(Eigen::AngleAxisd(0.4, Vector3d(0, 1, 1).normalized()));
  const Covariance P0 = coupledCovariance();
  ErrorStateEkf ekf(adisNoise(), kG);
  ekf.initialise(x0, P0);
  PositionMeasurement z;
  z.position = x0.position + Vector3d(0.2, -0.1, 0.05);
  z.sigma = 0.05;
  ekf.updatePosition(z);

  Eigen::Matrix<double, 3, 15> H = Eigen::Matrix<double, 3, 15>::Zero();
  H.leftCols<3>().setIdentity();
  const Matrix3d V = z.sigma * z.sigma * Matrix3d::Identity();
  const Eigen::Matrix<double, 15, 3> K =
      P0 * H.transpose() * (H * P0 * H.transpose() + V).inverse();
  const Eigen::Matrix<double, 15, 1> dx = K * (z.position - x0.position);
  const Covariance IKH = Covariance::Identity() - K * H;
  Covariance P = IKH * P0 * IKH.transpose() + K * V * K.transpose();
  Covariance G = Covariance::Identity();
  G.block<3, 3>(6, 6) -= skew(0.5 * dx.segment<3>(6));
  P = G * P * G.transpose();

  EXPECT_LT((ekf.covariance() - P).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((ekf.state().position - (x0.position + dx.segment<3>(0))).norm(), 1e-15);
  EXPECT_LT((ekf.state().velocity - dx.segment<3>(3)).norm(), 1e-15);
  const Quaterniond q = x0.attitude * quaternionFromRotationVector(dx.segment<3>(6));
  EXPECT_LT(angleBetween(ekf.state().attitude, q), 1e-15);
  EXPECT_LT((ekf.state().accel_bias - dx.segment<3>(9)).norm(), 1e-15);
  EXPECT_LT((ekf.state().gyro_bias - dx.segment<3>(12)).norm(), 1e-15);
  EXPECT_GT(dx.segment<3>(12).norm(), 1e-3);  // the coupling is real
}

TEST(ErrorStateEkf, AttitudeFixRotatesTheEstimateByTheGainAboutTheBodyAxis) {
  NavigationState x0;
  x0.attitude = Quaterniond(Eigen::AngleAxisd(1.0, Vector3d::UnitZ()));
  const double s0 = 0.05, s = 0.05;  // rad: equal, so the gain is 1/2
  ErrorStateEkf ekf(adisNoise(), kG);
  ekf.initialise(x0, diagonalCovariance(0.1, 0.1, s0, 0.1, 0.01));
  AttitudeMeasurement z;
  // 0.02 rad about the body x axis, which after the 1 rad yaw is not the world x axis.
  z.attitude = x0.attitude * quaternionFromRotationVector(Vector3d(0.02, 0.0, 0.0));
  z.sigma = s;
  ekf.updateAttitude(z);

  const Vector3d dtheta =
      rotationVectorFromQuaternion(x0.attitude.conjugate() * ekf.state().attitude);
  EXPECT_LT((dtheta - Vector3d(0.01, 0.0, 0.0)).norm(), 1e-15);
  // Posterior variance s0^2 s^2 / (s0^2 + s^2) = 1.25e-3, then the reset G = I - [dtheta/2]x
  // leaves the x axis alone and scales y and z by 1 + |dtheta/2|^2 (to second order exactly).
  const double v = 0.5 * s0 * s0;
  const Covariance& P = ekf.covariance();
  EXPECT_NEAR(P(6, 6), v, 1e-18);
  EXPECT_NEAR(P(7, 7), v * (1.0 + 0.005 * 0.005), 1e-18);
  EXPECT_NEAR(P(8, 8), v * (1.0 + 0.005 * 0.005), 1e-18);
  EXPECT_GT(P(7, 7) - v, 3e-8);  // the reset is applied
}

TEST(ErrorStateEkf, CovarianceStaysSymmetricAndPositiveDefiniteOverAFlight) {
  ErrorStateEkf ekf(adisNoise(), kG);
  ekf.initialise(NavigationState{}, diagonalCovariance(0.1, 0.1, 0.05, 0.2, 0.01));
  ImuMeasurement imu;
  for (int k = 1; k <= 5000; ++k) {
    imu.t = k / kImuRate;
    imu.gyro = {0.5 * std::sin(imu.t), 0.3 * std::cos(2 * imu.t), 0.2};
    imu.accel = {std::sin(3 * imu.t), 0.5, kG + std::cos(imu.t)};
    ekf.predict(imu);
    if (k % 5 == 0) {
      PositionMeasurement z;
      z.t = imu.t;
      z.position = ekf.state().position + Vector3d(1e-3, -2e-3, 5e-4);
      z.sigma = 1e-3;
      ekf.updatePosition(z);
    }
  }
  const Covariance& P = ekf.covariance();
  EXPECT_TRUE(P == P.transpose());
  Eigen::SelfAdjointEigenSolver<Covariance> eig(P);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
  // A millimetre fix every 10 ms holds the position to about a millimetre.
  EXPECT_LT(std::sqrt(P(0, 0)), 1e-3);
}

TEST(ErrorStateEkf, StationaryVehicleWithPoseFixesFindsTheImuBiases) {
  // Hovering, a biased but otherwise noise-free IMU, exact pose fixes at 100 Hz: the filter
  // must attribute the drift to the biases. The accelerometer's x and y biases are told apart
  // from a tilt only by the attitude fixes.
  const Vector3d b_a(0.05, -0.03, 0.1), b_w(0.01, -0.02, 0.005);
  ErrorStateEkf ekf(adisNoise(), kG);
  ekf.initialise(NavigationState{}, diagonalCovariance(1e-3, 0.01, 0.01, 0.2, 0.01));
  ImuMeasurement imu;
  imu.gyro = b_w;
  imu.accel = kG * Vector3d::UnitZ() + b_a;
  for (int k = 1; k <= 15000; ++k) {  // 30 s
    imu.t = k / kImuRate;
    ekf.predict(imu);
    if (k % 5 == 0) {
      ekf.updatePosition({imu.t, Vector3d::Zero(), 1e-3});
      ekf.updateAttitude({imu.t, Quaterniond::Identity(), 0.5 * M_PI / 180.0});
    }
  }
  EXPECT_LT((ekf.state().accel_bias - b_a).norm(), 2e-3);
  EXPECT_LT((ekf.state().gyro_bias - b_w).norm(), 1e-4);
  EXPECT_LT((ekf.angularVelocity()).norm(), 1e-4);
  EXPECT_LT((ekf.specificForce() - kG * Vector3d::UnitZ()).norm(), 2e-3);
}

TEST(ErrorStateEkf, BiasCorrectedOutputsSubtractTheEstimatedBiases) {
  NavigationState x0;
  x0.accel_bias = {0.1, 0.2, 0.3};
  x0.gyro_bias = {-0.01, 0.02, 0.03};
  ErrorStateEkf ekf(adisNoise(), kG);
  ekf.initialise(x0, Covariance::Identity());
  EXPECT_EQ(ekf.angularVelocity(), Vector3d::Zero());  // no sample yet
  ImuMeasurement imu;
  imu.t = 0.002;
  imu.gyro = {1.0, 2.0, 3.0};
  imu.accel = {0.0, 0.0, 9.0};
  ekf.predict(imu);
  EXPECT_LT((ekf.angularVelocity() - Vector3d(1.01, 1.98, 2.97)).norm(), 1e-15);
  EXPECT_LT((ekf.specificForce() - Vector3d(-0.1, -0.2, 8.7)).norm(), 1e-15);
}

TEST(ErrorStateEkf, RefusesToPredictBackwardsOrFuseAFixWithoutNoise) {
  ErrorStateEkf ekf(adisNoise(), kG);
  NavigationState x0;
  x0.t = 1.0;
  ekf.initialise(x0, Covariance::Identity());
  ImuMeasurement imu;
  imu.t = 0.5;
  EXPECT_THROW(ekf.predict(imu), std::invalid_argument);
  EXPECT_THROW(ekf.updatePosition({1.0, Vector3d::Zero(), 0.0}), std::invalid_argument);
}
