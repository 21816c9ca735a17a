#include "sim/rotor_model.h"

#include <cmath>

namespace cosim {

RotorModel::RotorModel(const QuadrotorParams& p)
    : k_f_(p.thrust_coefficient),
      w_min_(p.min_rotor_speed),
      w_max_(p.max_rotor_speed),
      tau_up_(p.time_constant_up),
      tau_down_(p.time_constant_down),
      delay_(p.motor_delay) {}

Eigen::Vector4d RotorModel::clamped(const Eigen::Vector4d& w) const {
  return w.cwiseMax(w_min_).cwiseMin(w_max_);
}

void RotorModel::command(const Eigen::Vector4d& speeds) {
  if (delay_ > 0.0)
    pending_.push_back({clock_ + delay_, clamped(speeds)});
  else
    commands_ = clamped(speeds);
}

void RotorModel::reset(const Eigen::Vector4d& speeds) {
  pending_.clear();
  commands_ = clamped(speeds);
  speeds_ = commands_;
}

void RotorModel::advance(double dt) {
  // Both gains are the same for every step of a run: cache them by dt.
  if (dt != cached_dt_) {
    cached_dt_ = dt;
    gain_up_ = 1.0 - std::exp(-dt / tau_up_);
    gain_down_ = 1.0 - std::exp(-dt / tau_down_);
  }
  // Delayed commands fall due on the clock; a nanosecond's slack absorbs the rounding of the
  // summed steps, so a delay of whole steps takes effect exactly that many steps late.
  while (!pending_.empty() && pending_.front().due <= clock_ + 1e-9) {
    commands_ = pending_.front().speeds;
    pending_.pop_front();
  }
  clock_ += dt;
  for (int i = 0; i < 4; ++i) {
    const double e = commands_[i] - speeds_[i];
    speeds_[i] += (e > 0.0 ? gain_up_ : gain_down_) * e;
  }
}

Eigen::Vector4d RotorModel::thrusts() const {
  return k_f_ * speeds_.cwiseProduct(speeds_);
}

}  // namespace cosim
