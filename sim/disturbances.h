#pragma once
// External disturbances applied to each quadrotor (ground robots feel none) as forces in MuJoCo (d->xfrc_applied, world
// frame), so that robustness can be evaluated:
// - rotor drag: a force against the velocity relative to the air, F = -k_d (v - w) (linear rotor
//   drag, as in Kai, Allibert, Hua and Hamel, "Nonlinear feedback control of quadrotors
//   exploiting first-order drag effects", IFAC 2017);
// - wind w = constant mean + gusts, the gusts a first-order Gauss-Markov (Ornstein-Uhlenbeck)
//   process per axis with standard deviation sigma and correlation time tau, seeded from the
//   scenario's seed (deterministic);
// - ground effect: thrust grows by 1 / (1 - (R / 4z)^2) near the floor (Cheeseman and Bennett,
//   "The effect of the ground on a helicopter rotor in forward flight", ARC R&M 3021, 1955),
//   capped at z = R/2, with R the rotor radius and z the height above the floor.
#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <vector>

#include "sim/disturbance_settings.h"
#include "sim/world_model.h"

namespace cosim {

class Disturbances {
 public:
  Disturbances(const DisturbanceSettings& settings, const WorldModel& world, double floor_z,
               std::uint64_t seed);
  // Sets xfrc_applied for every vehicle from the current state; call before each mj_step.
  void apply(const mjModel* m, mjData* d, double dt);
  const Eigen::Vector3d& currentWind() const { return wind_now_; }

 private:
  DisturbanceSettings s_;
  const WorldModel& world_;
  double floor_z_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  Eigen::Vector3d gust_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d wind_now_ = Eigen::Vector3d::Zero();
  std::vector<double> rotor_radius_;
};

}  // namespace cosim
