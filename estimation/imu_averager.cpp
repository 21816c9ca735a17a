#include "estimation/imu_averager.h"

#include <stdexcept>

namespace cosim {

ImuAverager::ImuAverager(double rate) : interval_(rate > 0.0 ? 1.0 / rate : 0.0) {
  if (!(rate > 0.0) || !(interval_ > 0.0))
    throw std::invalid_argument("ImuAverager: the prediction rate must be positive and finite");
  reset(0.0);
}

void ImuAverager::reset(double t) {
  last_t_ = t;
  next_due_ = t + interval_;
  span_ = 0.0;
  held_ = 0;
  gyro_dt_.setZero();
  accel_dt_.setZero();
}

bool ImuAverager::add(const ImuMeasurement& imu, ImuMeasurement& mean) {
  const double dt = imu.t - last_t_;
  if (!(dt > 0.0)) throw std::invalid_argument("ImuAverager: samples must come in time order");
  last_t_ = imu.t;
  span_ += dt;
  ++held_;
  gyro_dt_ += dt * imu.gyro;
  accel_dt_ += dt * imu.accel;
  // 1e-9 s: sample times built by adding periods are due on the tick they are meant for.
  if (imu.t < next_due_ - 1e-9) return false;
  if (held_ == 1) {
    mean = imu;  // a prediction per sample: the sample itself, to the bit
  } else {
    mean.t = imu.t;
    mean.gyro = gyro_dt_ / span_;
    mean.accel = accel_dt_ / span_;
  }
  next_due_ = imu.t + interval_;
  span_ = 0.0;
  held_ = 0;
  gyro_dt_.setZero();
  accel_dt_.setZero();
  return true;
}

}  // namespace cosim
