#include "sim/wind.h"

#include <cmath>

namespace cosim {

Wind::Wind(const DisturbanceSettings& s, std::uint64_t seed)
    : mean_(s.wind),
      sigma_(s.gust_sigma),
      tau_(s.gust_tau),
      rng_(seed ^ 0x9e3779b97f4a7c15ULL),
      velocity_(s.wind) {}

void Wind::advance(double dt) {
  if (sigma_ > 0) {
    const double a = std::exp(-dt / tau_);
    const double b = sigma_ * std::sqrt(1.0 - a * a);
    for (int i = 0; i < 3; ++i) gust_[i] = a * gust_[i] + b * normal_(rng_);
  }
  velocity_ = mean_ + gust_;
}

}  // namespace cosim
