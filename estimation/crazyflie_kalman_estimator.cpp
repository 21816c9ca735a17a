#include "estimation/crazyflie_kalman_estimator.h"

#include <cmath>
#include <stdexcept>

namespace cosim {
namespace {

// supervisor.c: flying while some motor ran above idle within the last 2000 ms.
constexpr std::int64_t kFlyingHysteresisTicks = 2000;

std::int64_t predictionInterval(double predict_rate) {
  if (!(predict_rate > 0.0) || !(predict_rate <= CrazyflieKalmanEstimator::kLoopRate))
    throw std::invalid_argument(
        "CrazyflieKalmanEstimator: the prediction rate must be in (0, 1000] Hz");
  // PREDICTION_UPDATE_INTERVAL_MS = 1000 / PREDICT_RATE, an integer division (1e-9: 1000 / 100
  // in doubles stays 10).
  return static_cast<std::int64_t>(
      std::floor(CrazyflieKalmanEstimator::kLoopRate / predict_rate + 1e-9));
}

}  // namespace

CrazyflieKalmanEstimator::CrazyflieKalmanEstimator(const CrazyflieKalmanParams& params,
                                                   double predict_rate)
    : core_(params), interval_ms_(predictionInterval(predict_rate)) {}

std::int64_t CrazyflieKalmanEstimator::tickAt(double t) {
  // 1e-6 ms: times built by adding periods fall on the tick they are meant for.
  return static_cast<std::int64_t>(std::ceil(t * kLoopRate - 1e-6));
}

void CrazyflieKalmanEstimator::initialise(double t, const Eigen::Vector3d& position,
                                          const Eigen::Vector3d& velocity,
                                          const Eigen::Quaterniond& attitude) {
  const Eigen::Quaterniond q = attitude.normalized();
  // The firmware set up for where the vehicle starts (kalman.initialX/Y/Z, initialYaw), so that
  // a reset by the supervisor starts there too.
  const double yaw = std::atan2(2.0 * (q.w() * q.z() + q.x() * q.y()),
                                1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z()));
  core_.setInitialPose(position, yaw);
  core_.init();
  core_.setState(position, q.conjugate() * velocity, q);
  next_tick_ = tickAt(t);
  last_prediction_ = next_tick_;
  next_prediction_ = next_tick_;
  last_noise_ = next_tick_;
  last_thrust_ = 0;
  thrust_seen_ = false;
  flying_ = false;
  reset_pending_ = false;
  resets_ = 0;
  predictions_ = 0;
  resetSubSamplers();
  accel_latest_.setZero();
  gyro_latest_.setZero();
  has_imu_ = false;
  imu_queue_.clear();
  imu_head_ = 0;
  fix_queue_.clear();
  fix_head_ = 0;
}

void CrazyflieKalmanEstimator::resetSubSamplers() {
  accel_sum_.setZero();
  gyro_sum_.setZero();
  accel_count_ = 0;
  accel_mean_.setZero();
  gyro_mean_.setZero();
}

void CrazyflieKalmanEstimator::addImu(const ImuMeasurement& imu) {
  imu_queue_.push_back(imu);
}

void CrazyflieKalmanEstimator::addPosition(const PositionMeasurement& z, double arrival) {
  if (!(z.sigma > 0.0))
    throw std::invalid_argument("CrazyflieKalmanEstimator: a fix's sigma must be positive");
  Fix& f = fix_queue_.emplace_back();
  f.tick = tickAt(arrival);
  f.is_position = true;
  f.position = z.position;
  f.sigma = z.sigma;
}

void CrazyflieKalmanEstimator::addAttitude(const AttitudeMeasurement& z, double arrival) {
  if (!(z.sigma > 0.0))
    throw std::invalid_argument("CrazyflieKalmanEstimator: a fix's sigma must be positive");
  Fix& f = fix_queue_.emplace_back();
  f.tick = tickAt(arrival);
  f.is_position = false;
  f.attitude = z.attitude;
  f.sigma = z.sigma;
}

void CrazyflieKalmanEstimator::advanceTo(double now, bool thrust_commanded) {
  const std::int64_t end = tickAt(now);
  for (; next_tick_ < end; ++next_tick_) runTick(next_tick_, thrust_commanded);
}

void CrazyflieKalmanEstimator::runTick(std::int64_t tick, bool thrust_commanded) {
  if (reset_pending_) {
    // estimatorKalmanInit: the filter as kalmanCoreInit leaves it, fresh sub-samplers.
    core_.init();
    last_prediction_ = tick;
    last_noise_ = tick;
    resetSubSamplers();
    reset_pending_ = false;
  }
  if (thrust_commanded) {
    last_thrust_ = tick;
    thrust_seen_ = true;
  }
  flying_ = thrust_seen_ && tick - last_thrust_ < kFlyingHysteresisTicks;

  if (tick >= next_prediction_) {
    // axis3fSubSamplerFinalize: the mean of the samples since the last prediction, if any.
    if (accel_count_ > 0) {
      accel_mean_ = accel_sum_ / accel_count_;
      gyro_mean_ = gyro_sum_ / accel_count_;
      accel_sum_.setZero();
      gyro_sum_.setZero();
      accel_count_ = 0;
    }
    core_.predict(accel_mean_, gyro_mean_, 1e-3 * static_cast<double>(tick - last_prediction_),
                  flying_);
    last_prediction_ = tick;
    next_prediction_ = tick + interval_ms_;
    ++predictions_;
  }

  core_.addProcessNoise(1e-3 * static_cast<double>(tick - last_noise_));
  last_noise_ = tick;

  for (; imu_head_ < imu_queue_.size() && tickAt(imu_queue_[imu_head_].t) <= tick; ++imu_head_) {
    const ImuMeasurement& z = imu_queue_[imu_head_];
    accel_sum_ += z.accel;
    gyro_sum_ += z.gyro;
    ++accel_count_;
    accel_latest_ = z.accel;
    gyro_latest_ = z.gyro;
    has_imu_ = true;
  }
  if (imu_head_ == imu_queue_.size()) {
    imu_queue_.clear();
    imu_head_ = 0;
  }
  for (; fix_head_ < fix_queue_.size() && fix_queue_[fix_head_].tick <= tick; ++fix_head_) {
    const Fix& f = fix_queue_[fix_head_];
    if (f.is_position) {
      core_.updatePosition(f.position, f.sigma);
    } else {
      core_.updateAttitude(f.attitude, f.sigma);
    }
  }
  if (fix_head_ == fix_queue_.size()) {
    fix_queue_.clear();
    fix_head_ = 0;
  }

  core_.finalize();
  if (!core_.withinBounds()) {
    reset_pending_ = true;
    ++resets_;
  }
}

}  // namespace cosim
