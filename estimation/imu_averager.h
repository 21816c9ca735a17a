#pragma once
// The IMU samples taken since the estimator's last prediction, averaged into the one sample the
// next prediction integrates. The Crazyflie's Kalman estimator predicts this way: its IMU runs at
// 1 kHz, but it predicts at PREDICT_RATE = RATE_100_HZ from the accelerometer and gyroscope
// sub-samplers, each the mean of the samples since the previous prediction, with dt the time
// since that prediction (crazyflie-firmware src/modules/src/estimator/estimator_kalman.c,
// kalmanTask). A sample holds over the interval it closes (ErrorStateEkf::predict), so the mean
// is weighted by each sample's interval: the exact integral of the held signal over the
// prediction interval (for evenly spaced samples the plain mean, as the firmware takes).
//
// A prediction is due at the first sample at or after the previous prediction plus the interval,
// and the next is due one interval after it (the firmware's nextPredictionMs = nowMs +
// interval): at 500 Hz samples and 100 Hz, every fifth sample. At a rate at or above the IMU's
// every sample is a prediction of its own, unchanged.
#include <Eigen/Core>

#include "estimation/measurements.h"

namespace cosim {

class ImuAverager {
 public:
  // rate: predictions per second (> 0, else std::invalid_argument).
  explicit ImuAverager(double rate);

  // Forgets the samples held; the last prediction was at t.
  void reset(double t);
  // Adds a sample (later than the previous one or the reset time, else std::invalid_argument).
  // Returns true if a prediction is due with it: then `mean` holds the interval-weighted mean of
  // the samples since the last prediction, stamped with this sample's time.
  bool add(const ImuMeasurement& imu, ImuMeasurement& mean);

  double interval() const { return interval_; }

 private:
  double interval_;
  double last_t_ = 0.0;    // the latest sample's time (the reset time before any)
  double next_due_ = 0.0;  // the time from which a sample closes a prediction interval
  double span_ = 0.0;      // s covered by the samples held
  int held_ = 0;           // samples held
  Eigen::Vector3d gyro_dt_ = Eigen::Vector3d::Zero();   // sum of gyro * dt
  Eigen::Vector3d accel_dt_ = Eigen::Vector3d::Zero();  // sum of accel * dt
};

}  // namespace cosim
