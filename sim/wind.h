#pragma once
// The air's velocity, the same everywhere in the world: a constant mean plus gusts, each gust
// component a first-order Gauss-Markov (Ornstein-Uhlenbeck) process with standard deviation
// sigma and correlation time tau, advanced by its exact discretisation and seeded from the
// scenario's seed (deterministic).
#include <Eigen/Core>
#include <cstdint>
#include <random>

#include "sim/disturbance_settings.h"

namespace cosim {

class Wind {
 public:
  Wind(const DisturbanceSettings& settings, std::uint64_t seed);
  // x_{k+1} = a x_k + sigma sqrt(1 - a^2) n, a = exp(-dt / tau), per axis.
  void advance(double dt);
  const Eigen::Vector3d& velocity() const { return velocity_; }

 private:
  Eigen::Vector3d mean_;
  double sigma_, tau_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  Eigen::Vector3d gust_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_;
};

}  // namespace cosim
