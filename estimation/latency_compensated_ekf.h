#pragma once
// The error-state EKF (estimation/error_state_ekf.h) fed with fixes that arrive late: a motion
// capture pose about 10 ms, a GPS position about 0.1 s after the instant it is valid for, while
// the IMU is sampled at 500 Hz. Such a fix is fused exactly by going back to its instant and
// filtering forward again: the reprocessing solution of the out-of-sequence measurement problem
// (Y. Bar-Shalom, "Update with out-of-sequence measurements in tracking: exact solution", IEEE
// Trans. Aerospace and Electronic Systems 38(3), 2002, whose retrodiction avoids the storage but
// is exact only for a linear model).
//
// The filter predicts at its own rate, not at every IMU sample: from the mean of the samples
// since the previous prediction, over the interval since it (estimation/imu_averager.h), as the
// Crazyflie's Kalman estimator does at 100 Hz from a 1 kHz IMU. A bounded history keeps, for
// every prediction step, the averaged sample and the filter's state and covariance after it. A
// fix valid at t is fused at t itself: from the last history entry before t the filter predicts
// over the partial interval to exactly t (with that step's averaged sample), applies the fix,
// finishes the interval and re-runs the stored steps (and the fixes stored after t) up to the
// latest. The result is the one a filter fusing every fix on time and in time order would give,
// whatever the order the fixes arrive in, as long as each arrives within the history window.
//
// The estimate (current()) is the posterior at the latest prediction, as the firmware's
// estimator hands its controllers the state of its latest prediction and update; the body rates
// and specific force come from the latest IMU sample itself (angularVelocity, specificForce).
//
// Fusing on arrival (FixTiming::OnArrival) is what the Crazyflie's Kalman estimator does
// instead: crazyflie-firmware's estimator_kalman.c dequeues each external position or pose at
// its next 1 kHz loop and applies it to the state of its latest prediction
// (kalmanCoreUpdateWithPosition / kalmanCoreUpdateWithPose) with no regard for when it was
// valid, so a motion capture fix's latency shows in the estimate as it does on the vehicle.
// Then a fix updates the latest prediction's posterior directly and nothing is stored or re-run.
//
// The history holds ceil(max_latency * step_rate) + 2 steps (step_rate the lower of the
// prediction and IMU rates); a fix no later than the oldest step is dropped and counted. A fix
// valid after the latest prediction waits for the next. Re-running is done lazily, once for all
// the fixes added between two reads, so a motion capture position and attitude of the same
// instant cost one replay, not two.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "estimation/error_state_ekf.h"
#include "estimation/fix_timing.h"
#include "estimation/imu_averager.h"

namespace cosim {

class LatencyCompensatedEkf {
 public:
  // max_latency: s, how far behind the latest IMU sample a fix's validity time may lie (the
  // sensor's latency plus however late the caller delivers); imu_rate: Hz, the IMU's;
  // predict_rate: Hz, the predictions' (at or above imu_rate: one per sample).
  LatencyCompensatedEkf(const ImuNoise& noise, double gravity, double max_latency, double imu_rate,
                        double predict_rate, FixTiming timing = FixTiming::AtValidity);

  // Starts from x (at x.t) with error covariance P0; forgets the history and every stored fix.
  void initialise(const NavigationState& x, const ErrorStateEkf::Covariance& P0);

  // The next IMU sample; imu.t must exceed the latest one's (std::invalid_argument otherwise).
  // Predicts when a prediction is due.
  void addImu(const ImuMeasurement& imu);
  // A fix valid at z.t. Returns false (and counts it) if it is too old for the history. On
  // arrival (FixTiming::OnArrival) z.t is not used: the fix is fused at once, never dropped.
  bool addPosition(const PositionMeasurement& z);
  bool addAttitude(const AttitudeMeasurement& z);

  // The estimate at the latest prediction's time, every fix valid up to then fused. The getters
  // finish any pending replay first (which is why the history is mutable).
  const NavigationState& current() const;
  const ErrorStateEkf::Covariance& covariance() const;
  // The latest IMU sample corrected by the current bias estimates (zero before the first).
  Eigen::Vector3d angularVelocity() const;
  Eigen::Vector3d specificForce() const;

  std::size_t droppedMeasurements() const { return dropped_; }
  // Fixes stored and valid after the latest prediction, still waiting for the next.
  std::size_t waitingMeasurements() const;
  // A fix must be valid strictly after this instant (the oldest history entry) to be fused.
  double windowStart() const { return step(0).state.t; }
  std::size_t historyCapacity() const { return steps_.size(); }

 private:
  // One prediction step: the averaged sample that closes it and the filter's posterior then.
  struct Step {
    ImuMeasurement imu;
    NavigationState state;
    ErrorStateEkf::Covariance P;
  };
  // A stored fix, kept until it falls out of the history (a replay must fuse it again).
  struct Fix {
    enum Kind : int { kPosition = 0, kAttitude = 1 };
    double t = 0.0;
    Kind kind = kPosition;
    std::uint64_t arrival = 0;  // breaks ties between fixes of one kind and instant
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();
    double sigma = 0.0;
  };

  bool addFix(const Fix& fix);
  // Fuses `fix` into the latest prediction's posterior (FixTiming::OnArrival).
  void fuseNow(const Fix& fix);
  // Appends a prediction step closed by the averaged sample `imu`.
  void addStep(const ImuMeasurement& imu);
  // Re-runs steps dirty_from_ .. last from the one before (a no-op when nothing is dirty).
  void replay() const;
  Step& step(std::size_t i) const { return steps_[(first_ + i) % steps_.size()]; }

  mutable ErrorStateEkf ekf_;
  mutable std::vector<Step> steps_;  // ring buffer, step(0) the oldest
  std::size_t first_ = 0;
  std::size_t count_ = 0;
  mutable std::size_t dirty_from_ = 0;  // first step to recompute; count_ when none
  // The step whose posterior ekf_ holds (kNone: none), so that extending the history by one
  // sample needs no restore.
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  mutable std::size_t ekf_holds_ = kNone;
  std::vector<Fix> fixes_;  // ordered by (t, kind, arrival)
  std::uint64_t arrivals_ = 0;
  std::size_t dropped_ = 0;
  FixTiming timing_;
  ImuAverager averager_;
  ImuMeasurement latest_imu_;  // the latest raw sample (valid when has_imu_)
  bool has_imu_ = false;
};

}  // namespace cosim
