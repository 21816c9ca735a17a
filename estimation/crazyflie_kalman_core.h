#pragma once
// The Crazyflie's Kalman estimator, the filter itself (crazyflie-firmware
// src/modules/src/kalman_core/kalman_core.c and mm_pose.c / mm_position.c, read for their
// equations; the schedule that drives it is estimation/crazyflie_kalman_estimator.h). After
// M. W. Mueller, M. Hamer, R. D'Andrea, "Fusing ultra-wideband range measurements with
// accelerometers and rate gyroscopes for quadrocopter state estimation", ICRA 2015 (the model),
// and M. W. Mueller, M. Hehn, R. D'Andrea, "Covariance correction step for Kalman filtering with
// an attitude", J. Guidance, Control, and Dynamics, 2016, doi 10.2514/1.G000848 (the attitude
// reset).
//
// State (9): position x in the world, velocity p in the BODY frame, attitude error d (3) about a
// reference quaternion q (body to world) that the error is folded into after every update
// (finalize), so d is zero at the start of every prediction; covariance P, 9 x 9. No IMU biases:
// the firmware's sensor task removes the gyroscope's bias, measured at rest, before the estimator
// sees it (src/hal/src/sensors_bmi088_bmp3xx.c, processGyroBias).
//
// Model (ICRA 2015, Sec. III; kalman_core.c predictDt), with omega the gyroscope and R = R(q):
//   x' = R p,   p' = a - omega x p - g R^T e3,   q' = q (x) (0, omega / 2).
// While flying, a = (0, 0, a_z): "thrust can only be produced in the body's Z direction", so the
// accelerometer's x and y (rotor drag, mostly) are ignored and the filter's horizontal velocity
// follows the tilt alone; on the ground the whole accelerometer is used. Builds with the drag
// term subtract dragB (p + omega x cop) while flying (CrazyflieKalmanParams::drag_b).
//
// Every number the firmware bounds is bounded here too: after every change P is made symmetric
// and each entry held to at most MAX_COVARIANCE = 100, each variance to at least MIN_COVARIANCE =
// 1e-6 (kalman_core.c). Doubles throughout (the firmware computes in float).
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "estimation/crazyflie_kalman_params.h"

namespace cosim {

class CrazyflieKalmanCore {
 public:
  static constexpr int kDim = 9;
  using Covariance = Eigen::Matrix<double, kDim, kDim>;
  using StateVector = Eigen::Matrix<double, kDim, 1>;
  // Where each 3-vector of the state starts (KC_STATE_X, KC_STATE_PX, KC_STATE_D0).
  static constexpr int kPosition = 0;
  static constexpr int kVelocity = 3;
  static constexpr int kAttitude = 6;

  explicit CrazyflieKalmanCore(const CrazyflieKalmanParams& params);

  // kalmanCoreInit: the state at params.initial_position, at rest, level at params.initial_yaw;
  // P diagonal from the initial standard deviations.
  void init();
  // kalman.initialX/Y/Z and initialYaw: where init() (and so a reset) starts the state.
  void setInitialPose(const Eigen::Vector3d& position, double yaw) {
    params_.initial_position = position;
    params_.initial_yaw = yaw;
  }
  // Overrides the state after init() (the covariance is kept): for a filter that has converged
  // on the ground before the flight begins. body_velocity in the body frame of `attitude`.
  void setState(const Eigen::Vector3d& position, const Eigen::Vector3d& body_velocity,
                const Eigen::Quaterniond& attitude);

  // predictDt: one prediction over dt (s) from the averaged accelerometer (specific force, m/s^2)
  // and gyroscope (rad/s) samples, body frame. Leaves R as it was (finalize recomputes it).
  void predict(const Eigen::Vector3d& accel, const Eigen::Vector3d& gyro, double dt, bool flying);
  // addProcessNoiseDt: the process noise of dt seconds, added to P's diagonal.
  void addProcessNoise(double dt);
  // kalmanCoreUpdateWithPosition: three scalar updates of x, y, z; std in m (> 0).
  void updatePosition(const Eigen::Vector3d& position, double std);
  // The attitude half of kalmanCoreUpdateWithPose; std in rad (> 0).
  void updateAttitude(const Eigen::Quaterniond& attitude, double std);
  // kalmanCoreFinalize: folds the attitude error into q (rotating P's attitude block, Mueller
  // 2017), recomputes R, zeroes d. Returns false (doing nothing) if nothing changed since the
  // last finalize.
  bool finalize();
  // kalmanSupervisorIsStateWithinBounds.
  bool withinBounds() const;

  const StateVector& state() const { return S_; }
  const Covariance& covariance() const { return P_; }
  const Eigen::Quaterniond& attitude() const { return q_; }
  const Eigen::Matrix3d& rotation() const { return R_; }
  Eigen::Vector3d position() const { return S_.segment<3>(kPosition); }
  Eigen::Vector3d bodyVelocity() const { return S_.segment<3>(kVelocity); }
  // kalmanCoreExternalizeState: the body velocity rotated into the world by R.
  Eigen::Vector3d worldVelocity() const { return R_ * S_.segment<3>(kVelocity); }
  const CrazyflieKalmanParams& params() const { return params_; }

 private:
  // kalmanCoreScalarUpdate with H selecting state `index`.
  void scalarUpdate(int index, double error, double std);
  // Symmetric, and every entry within the firmware's bounds.
  void boundCovariance();
  // The firmware's bounds for one entry (the diagonal also at least MIN_COVARIANCE).
  static double bounded(double v, bool diagonal);

  CrazyflieKalmanParams params_;
  StateVector S_ = StateVector::Zero();
  Eigen::Quaterniond q_ = Eigen::Quaterniond::Identity();
  Eigen::Quaterniond initial_q_ = Eigen::Quaterniond::Identity();
  Eigen::Matrix3d R_ = Eigen::Matrix3d::Identity();
  Covariance P_ = Covariance::Identity();
  bool updated_ = false;  // the firmware's isUpdated
  // P is symmetric and within bounds (false after init and predict): then adding process noise
  // can only push a variance past MAX_COVARIANCE, and a finalize that folds nothing changes
  // nothing, so the firmware's full pass over P after each reduces to the diagonal or to none.
  bool bounded_ = false;
};

}  // namespace cosim
