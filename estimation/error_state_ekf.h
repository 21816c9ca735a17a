#pragma once
// The error-state (indirect) extended Kalman filter of an IMU-driven vehicle, after J. Solà,
// "Quaternion kinematics for the error-state Kalman filter", arXiv:1711.02508, 2017 (equation
// numbers of that version), with the local (body-frame) attitude error and gravity known:
// - the nominal state (NavigationState) is integrated from each IMU sample (Sec. 5.4.1, eq. 260);
// - the 15-dim error state dx = [dp, dv, dtheta, da_b, dw_b] (true = nominal (+) dx, with
//   q_true = q (x) Exp(dtheta)) has the covariance P, propagated with the Jacobians of Sec. 5.4.3
//   (eqs. 262-264, F_x of eq. 269 without its gravity row and column, F_i Q_i F_i^T of eq. 270);
// - a position or attitude fix updates dx and P (Sec. 6.1, with the Joseph form of P), the mean
//   of dx is injected into the nominal state (Sec. 6.2) and the error reset (Sec. 6.3, G = I -
//   [dtheta/2]x on the attitude block).
// Process noise: the IMU's white noise and bias random walk given as continuous-time densities
// (the Kalibr model, see ImuNoise), so a step of dt adds sigma^2 dt to the variance of each:
// Solà's V_i = sigma_an^2 dt^2 with the sample noise sigma_an = density / sqrt(dt).
//
// Speed: predict() runs at the prediction rate (100 Hz by default), and again for every step a
// late fix makes the filter re-run, for every vehicle, so the covariance is propagated block by
// block, skipping the identity and zero blocks of F (about 650 multiply-adds, against 6750 for
// two dense 15 x 15 products).
#include <Eigen/Core>

#include "estimation/measurements.h"
#include "estimation/navigation_state.h"

namespace cosim {

class ErrorStateEkf {
 public:
  static constexpr int kDim = 15;
  using Covariance = Eigen::Matrix<double, kDim, kDim>;
  // Where each 3-vector of the error state starts.
  static constexpr int kPosition = 0;
  static constexpr int kVelocity = 3;
  static constexpr int kAttitude = 6;
  static constexpr int kAccelBias = 9;
  static constexpr int kGyroBias = 12;

  // gravity: m/s^2, acting along -z of the world frame.
  ErrorStateEkf(const ImuNoise& noise, double gravity);

  // Starts (or restarts) from x with error covariance P0 (made symmetric); forgets the last IMU
  // sample.
  void initialise(const NavigationState& x, const Covariance& P0);

  // Propagates state and covariance from state().t to imu.t, taking the sample as constant over
  // the interval (the sample closing it). Throws std::invalid_argument if imu.t < state().t.
  void predict(const ImuMeasurement& imu) { predictTo(imu.t, imu); }
  // The same over part of the interval, to t (state().t <= t): for a fix valid between samples.
  void predictTo(double t, const ImuMeasurement& imu);

  // Fuse a fix at the current state time (the caller predicts to z.t first). Throw
  // std::invalid_argument if z.sigma is not positive.
  void updatePosition(const PositionMeasurement& z);
  // Innovation: the rotation vector of q_est^-1 (x) q_meas, in the body frame, whose Jacobian with
  // respect to dx is [0 0 I 0 0].
  void updateAttitude(const AttitudeMeasurement& z);

  const NavigationState& state() const { return x_; }
  const Covariance& covariance() const { return P_; }
  // The last IMU sample corrected by the current bias estimates (zero before the first sample):
  // what a controller uses as the body rates and the body-frame specific force.
  Eigen::Vector3d angularVelocity() const;
  Eigen::Vector3d specificForce() const;

  const ImuNoise& noise() const { return noise_; }
  double gravity() const { return gravity_; }

 private:
  // The Kalman update for a fix that observes the 3-vector of the error state at `block`
  // directly (H = [0 .. I .. 0]), with residual r and noise variance sigma^2 per axis.
  void updateBlock(int block, const Eigen::Vector3d& r, double sigma);
  void propagateCovariance(const Eigen::Matrix3d& R, const Eigen::Vector3d& a,
                           const Eigen::Matrix3d& dR, double dt);

  ImuNoise noise_;
  double gravity_;
  NavigationState x_;
  Covariance P_ = Covariance::Identity();
  ImuMeasurement last_imu_;
  bool has_imu_ = false;
};

}  // namespace cosim
