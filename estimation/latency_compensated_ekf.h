#pragma once
// The error-state EKF (estimation/error_state_ekf.h) fed with fixes that arrive late: a motion
// capture pose about 10 ms, a GPS position about 0.1 s after the instant it is valid for, while
// the IMU is sampled at 500 Hz. Such a fix is fused exactly by going back to its instant and
// filtering forward again: the reprocessing solution of the out-of-sequence measurement problem
// (Y. Bar-Shalom, "Update with out-of-sequence measurements in tracking: exact solution", IEEE
// Trans. Aerospace and Electronic Systems 38(3), 2002, whose retrodiction avoids the storage but
// is exact only for a linear model). A bounded history keeps, for every IMU step, the sample and
// the filter's state and covariance after it. A fix valid at t is fused at t itself: from the
// last history entry before t the filter predicts over the partial interval to exactly t,
// applies the fix, finishes that IMU interval and re-runs the stored samples (and the fixes
// stored after t) up to the latest sample. The result is the one a filter fusing every fix on
// time and in time order would give, whatever the order the fixes arrive in, as long as each
// arrives within the history window.
//
// The history holds ceil(max_latency * imu_rate) + 2 steps; a fix no later than the oldest step
// is dropped and counted. A fix valid after the latest IMU sample waits until the IMU reaches
// it. Re-running is done lazily, once for all the fixes added between two reads, so a motion
// capture position and attitude of the same instant cost one replay, not two.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "estimation/error_state_ekf.h"

namespace cosim {

class LatencyCompensatedEkf {
 public:
  // max_latency: s, how far behind the latest IMU sample a fix's validity time may lie (the
  // sensor's latency plus however late the caller delivers); imu_rate: Hz, sizes the history.
  LatencyCompensatedEkf(const ImuNoise& noise, double gravity, double max_latency, double imu_rate);

  // Starts from x (at x.t) with error covariance P0; forgets the history and every stored fix.
  void initialise(const NavigationState& x, const ErrorStateEkf::Covariance& P0);

  // The next IMU sample; imu.t must exceed the latest one's (std::invalid_argument otherwise).
  void addImu(const ImuMeasurement& imu);
  // A fix valid at z.t. Returns false (and counts it) if it is too old for the history.
  bool addPosition(const PositionMeasurement& z);
  bool addAttitude(const AttitudeMeasurement& z);

  // The estimate at the latest IMU sample's time, every fix valid up to then fused. The getters
  // finish any pending replay first (which is why the history is mutable).
  const NavigationState& current() const;
  const ErrorStateEkf::Covariance& covariance() const;
  // The latest IMU sample corrected by the current bias estimates (zero before the first).
  Eigen::Vector3d angularVelocity() const;
  Eigen::Vector3d specificForce() const;

  std::size_t droppedMeasurements() const { return dropped_; }
  // Fixes stored and valid after the latest IMU sample, still waiting for it.
  std::size_t waitingMeasurements() const;
  // A fix must be valid strictly after this instant (the oldest history entry) to be fused.
  double windowStart() const { return step(0).state.t; }
  std::size_t historyCapacity() const { return steps_.size(); }

 private:
  // One IMU step: the sample that closes it and the filter's posterior at its time.
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
};

}  // namespace cosim
