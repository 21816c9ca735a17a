#pragma once
// What a scenario's `disturbances:` section asks for (see sim/disturbances.h for the models).
#include <Eigen/Core>

namespace cosim {

struct DisturbanceSettings {
  double drag_coefficient = 0.0;  // k_d, N per m/s
  Eigen::Vector3d wind = Eigen::Vector3d::Zero();  // mean wind, m/s (world)
  double gust_sigma = 0.0;        // m/s, standard deviation of each gust component
  double gust_tau = 2.0;          // s, gust correlation time
  bool ground_effect = false;
  bool any() const {
    return drag_coefficient > 0 || wind.squaredNorm() > 0 || gust_sigma > 0 || ground_effect;
  }
};

}  // namespace cosim
