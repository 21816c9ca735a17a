#include "estimation/latency_compensated_ekf.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cosim {

LatencyCompensatedEkf::LatencyCompensatedEkf(const ImuNoise& noise, double gravity,
                                             double max_latency, double imu_rate,
                                             double predict_rate, FixTiming timing)
    : ekf_(noise, gravity), timing_(timing), averager_(predict_rate) {
  const double step_rate = std::min(imu_rate, predict_rate);
  if (!(max_latency >= 0.0) || !(imu_rate > 0.0) || !(max_latency * step_rate < 1e6)) {
    throw std::invalid_argument(
        "LatencyCompensatedEkf: max_latency must be >= 0 and the rates > 0, latency times rate "
        "< 1e6");
  }
  // The steps spanning max_latency, one more so that a fix exactly max_latency old still has a
  // step before it, and one for the base the first of those is re-run from. The 1e-9 keeps
  // 0.01 s * 500 Hz at 5 steps despite rounding.
  const auto n = static_cast<std::size_t>(std::ceil(max_latency * step_rate - 1e-9)) + 2;
  steps_.resize(n);
  initialise(NavigationState{}, ErrorStateEkf::Covariance::Identity());
}

void LatencyCompensatedEkf::initialise(const NavigationState& x,
                                       const ErrorStateEkf::Covariance& P0) {
  ekf_.initialise(x, P0);
  first_ = 0;
  count_ = 1;
  Step& base = step(0);
  base.imu = ImuMeasurement{};
  base.imu.t = x.t;
  base.state = ekf_.state();
  base.P = ekf_.covariance();
  dirty_from_ = count_;
  ekf_holds_ = 0;
  fixes_.clear();
  arrivals_ = 0;
  dropped_ = 0;
  averager_.reset(x.t);
  has_imu_ = false;
}

void LatencyCompensatedEkf::addImu(const ImuMeasurement& imu) {
  ImuMeasurement mean;
  const bool due = averager_.add(imu, mean);  // throws, unchanged, on a sample out of order
  latest_imu_ = imu;
  has_imu_ = true;
  if (due) addStep(mean);
}

void LatencyCompensatedEkf::addStep(const ImuMeasurement& imu) {
  // The newest step must be up to date before it is extended, and the second oldest before it
  // becomes the base everything later is re-run from.
  replay();
  if (!(imu.t > step(count_ - 1).imu.t)) {
    throw std::invalid_argument("LatencyCompensatedEkf: IMU samples must come in time order");
  }
  if (count_ == steps_.size()) {
    first_ = (first_ + 1) % steps_.size();
    --count_;
    if (ekf_holds_ != kNone) ekf_holds_ = ekf_holds_ > 0 ? ekf_holds_ - 1 : kNone;
    // Fixes up to the new base are in every stored state and are never re-run again.
    const double base_t = step(0).imu.t;
    const auto keep =
        std::find_if(fixes_.begin(), fixes_.end(), [&](const Fix& f) { return f.t > base_t; });
    fixes_.erase(fixes_.begin(), keep);
  }
  step(count_).imu = imu;
  ++count_;
  dirty_from_ = count_ - 1;
}

bool LatencyCompensatedEkf::addPosition(const PositionMeasurement& z) {
  Fix f;
  f.t = z.t;
  f.kind = Fix::kPosition;
  f.position = z.position;
  f.sigma = z.sigma;
  return addFix(f);
}

bool LatencyCompensatedEkf::addAttitude(const AttitudeMeasurement& z) {
  Fix f;
  f.t = z.t;
  f.kind = Fix::kAttitude;
  f.attitude = z.attitude;
  f.sigma = z.sigma;
  return addFix(f);
}

bool LatencyCompensatedEkf::addFix(const Fix& fix) {
  if (timing_ == FixTiming::OnArrival) {
    if (!(fix.sigma > 0.0)) throw std::invalid_argument("LatencyCompensatedEkf: sigma must be > 0");
    fuseNow(fix);
    return true;
  }
  if (!(fix.t > windowStart())) {
    ++dropped_;
    return false;
  }
  if (!(fix.sigma > 0.0)) throw std::invalid_argument("LatencyCompensatedEkf: sigma must be > 0");
  Fix f = fix;
  f.arrival = arrivals_++;
  // Fused in (t, kind, arrival) order, so that the arrival order of fixes of different
  // instants, or of a position and an attitude of the same instant, does not matter.
  const auto at = std::upper_bound(fixes_.begin(), fixes_.end(), f, [](const Fix& a, const Fix& b) {
    return a.t < b.t || (a.t == b.t && a.kind < b.kind);
  });
  fixes_.insert(at, f);

  // The step whose interval (previous sample, its sample] holds t must be re-run, and all after.
  if (f.t <= step(count_ - 1).imu.t) {
    std::size_t lo = 1, hi = count_ - 1;  // the first step with imu.t >= t, by bisection
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (step(mid).imu.t < f.t) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
    dirty_from_ = std::min(dirty_from_, lo);
  }
  return true;
}

void LatencyCompensatedEkf::fuseNow(const Fix& fix) {
  // After replay() ekf_ holds the latest prediction's posterior: on arrival nothing is ever
  // re-run, so the filter itself is the latest step's covariance and the steps store only
  // their states (covariance()).
  replay();
  Step& latest = step(count_ - 1);
  const double t = latest.state.t;
  if (fix.kind == Fix::kPosition) {
    ekf_.updatePosition({t, fix.position, fix.sigma});
  } else {
    ekf_.updateAttitude({t, fix.attitude, fix.sigma});
  }
  latest.state = ekf_.state();
}

void LatencyCompensatedEkf::replay() const {
  if (dirty_from_ >= count_) return;
  const Step& base = step(dirty_from_ - 1);
  // (Only a fix fused at its validity, into a step before the latest, gets here with ekf_
  // elsewhere: on arrival the filter always holds the latest step, whose P is not stored.)
  if (ekf_holds_ != dirty_from_ - 1) ekf_.initialise(base.state, base.P);
  auto fix = std::upper_bound(fixes_.begin(), fixes_.end(), base.imu.t,
                              [](double t, const Fix& f) { return t < f.t; });
  for (std::size_t k = dirty_from_; k < count_; ++k) {
    Step& s = step(k);
    for (; fix != fixes_.end() && fix->t <= s.imu.t; ++fix) {
      ekf_.predictTo(fix->t, s.imu);
      if (fix->kind == Fix::kPosition) {
        ekf_.updatePosition({fix->t, fix->position, fix->sigma});
      } else {
        ekf_.updateAttitude({fix->t, fix->attitude, fix->sigma});
      }
    }
    ekf_.predict(s.imu);
    s.state = ekf_.state();
    if (timing_ == FixTiming::AtValidity) s.P = ekf_.covariance();  // a base to re-run from
  }
  dirty_from_ = count_;
  ekf_holds_ = count_ - 1;
}

const NavigationState& LatencyCompensatedEkf::current() const {
  replay();
  return step(count_ - 1).state;
}

const ErrorStateEkf::Covariance& LatencyCompensatedEkf::covariance() const {
  replay();
  return timing_ == FixTiming::OnArrival ? ekf_.covariance() : step(count_ - 1).P;
}

Eigen::Vector3d LatencyCompensatedEkf::angularVelocity() const {
  if (!has_imu_) return Eigen::Vector3d::Zero();
  return latest_imu_.gyro - current().gyro_bias;
}

Eigen::Vector3d LatencyCompensatedEkf::specificForce() const {
  if (!has_imu_) return Eigen::Vector3d::Zero();
  return latest_imu_.accel - current().accel_bias;
}

std::size_t LatencyCompensatedEkf::waitingMeasurements() const {
  const double latest = step(count_ - 1).imu.t;
  return static_cast<std::size_t>(
      std::count_if(fixes_.begin(), fixes_.end(), [&](const Fix& f) { return f.t > latest; }));
}

}  // namespace cosim
