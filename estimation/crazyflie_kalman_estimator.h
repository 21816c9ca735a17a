#pragma once
// The Crazyflie's Kalman estimator as its task runs it (crazyflie-firmware
// src/modules/src/estimator/estimator_kalman.c, kalmanTask, read for its schedule; the filter is
// estimation/crazyflie_kalman_core.h). The task wakes at every tick of the stabilizer loop
// (RATE_MAIN_LOOP, 1 kHz, whole milliseconds) and, in this order:
//   1. resets the filter if the supervisor asked for it at the previous tick;
//   2. predicts if a prediction is due (every PREDICTION_UPDATE_INTERVAL_MS = 1000 / PREDICT_RATE
//      ms, RATE_100_HZ: 10 ms), from the means of the accelerometer and gyroscope samples taken
//      since the previous prediction (the sub-samplers; with no new sample, the previous means),
//      over the time since it, flying or not as the supervisor says;
//   3. adds the process noise of the time since the previous tick ("every loop, rather than every
//      prediction": the noise a second adds depends on the loop's rate, 1 kHz here as there);
//   4. takes every queued measurement: IMU samples into the sub-samplers, each position and pose
//      into the filter at once (no regard for when it was valid: fusion on arrival);
//   5. finalizes (folds the attitude error in), checks the supervisor's bounds;
//   6. externalizes the state, which the stabilizer reads at its NEXT tick: the controller at
//      tick k sees the state as the task left it after tick k - 1.
// Flying (supervisorIsFlying): some motor was commanded above idle within the last 2 s
// (supervisor.c, IS_FLYING_HYSTERESIS_THRESHOLD = 2000 ms).
//
// The caller hands over the IMU samples (each taken by the task at the first tick at or after
// its time), the fixes with the time they reach the vehicle, and whether thrust is commanded, and
// advances the task to the present (advanceTo).
#include <cstdint>
#include <vector>

#include "estimation/crazyflie_kalman_core.h"
#include "estimation/measurements.h"

namespace cosim {

class CrazyflieKalmanEstimator {
 public:
  static constexpr double kLoopRate = 1000.0;  // Hz, RATE_MAIN_LOOP
  // predict_rate: Hz; the interval is 1000 / predict_rate whole milliseconds (the firmware's
  // integer division), at least one loop: predict_rate in (0, 1000], else std::invalid_argument.
  CrazyflieKalmanEstimator(const CrazyflieKalmanParams& params, double predict_rate);

  // Starts the task at time t (its first tick the one at or after t) with the filter as
  // kalmanCoreInit leaves it, then at the given state (position, world velocity, attitude: a
  // filter that has settled before the flight); forgets every queued measurement.
  void initialise(double t, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                  const Eigen::Quaterniond& attitude);

  // Queues an IMU sample, taken at the first tick at or after imu.t (samples in time order).
  void addImu(const ImuMeasurement& imu);
  // Queues a fix that reaches the vehicle at `arrival` (s); z.t is not used, z.sigma is the
  // standard deviation the filter weighs it with (locSrv.extPosStdDev, extQuatStdDev; > 0).
  void addPosition(const PositionMeasurement& z, double arrival);
  void addAttitude(const AttitudeMeasurement& z, double arrival);

  // Runs every tick before `now` (the state the stabilizer reads at now); thrust_commanded: some
  // motor is commanded above idle over those ticks.
  void advanceTo(double now, bool thrust_commanded);

  // The externalized state: position and velocity in the world, attitude body to world.
  Eigen::Vector3d position() const { return core_.position(); }
  Eigen::Vector3d velocity() const { return core_.worldVelocity(); }
  const Eigen::Quaterniond& attitude() const { return core_.attitude(); }
  // The latest IMU sample the task has taken (zero before the first): what the firmware's
  // controllers read as body rates and specific force.
  const Eigen::Vector3d& latestGyro() const { return gyro_latest_; }
  const Eigen::Vector3d& latestAccel() const { return accel_latest_; }
  bool hasImu() const { return has_imu_; }

  const CrazyflieKalmanCore& core() const { return core_; }
  bool flying() const { return flying_; }
  // Resets by the supervisor since initialise (a state beyond kalman.maxPos / maxVel).
  std::size_t resets() const { return resets_; }
  std::int64_t predictions() const { return predictions_; }

 private:
  struct Fix {
    std::int64_t tick = 0;  // the first tick at or after its arrival
    bool is_position = true;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();
    double sigma = 0.0;
  };
  // The tick (ms count) at or after t.
  static std::int64_t tickAt(double t);
  void runTick(std::int64_t tick, bool thrust_commanded);
  void resetSubSamplers();

  CrazyflieKalmanCore core_;
  std::int64_t interval_ms_;
  std::int64_t next_tick_ = 0;
  std::int64_t last_prediction_ = 0;
  std::int64_t next_prediction_ = 0;
  std::int64_t last_noise_ = 0;
  std::int64_t last_thrust_ = 0;
  bool thrust_seen_ = false;
  bool flying_ = false;
  bool reset_pending_ = false;
  std::size_t resets_ = 0;
  std::int64_t predictions_ = 0;

  // The sub-samplers: sums and counts since the last prediction, and the means it used.
  Eigen::Vector3d accel_sum_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_sum_ = Eigen::Vector3d::Zero();
  int accel_count_ = 0;
  Eigen::Vector3d accel_mean_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_mean_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_latest_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_latest_ = Eigen::Vector3d::Zero();
  bool has_imu_ = false;

  // Queues, in arrival order, consumed from their heads (cleared when empty: no allocation once
  // they have grown to a control period's worth).
  std::vector<ImuMeasurement> imu_queue_;
  std::size_t imu_head_ = 0;
  std::vector<Fix> fix_queue_;
  std::size_t fix_head_ = 0;
};

}  // namespace cosim
