#pragma once
// The static world a plan is made in: axis-aligned bounds and a list of obstacles.
#include <limits>
#include <vector>

#include "planning/world/obstacle.h"

namespace cosim {

struct World {
  Eigen::Vector3d bounds_min = Eigen::Vector3d::Zero();
  Eigen::Vector3d bounds_max = Eigen::Vector3d::Zero();
  std::vector<Obstacle> obstacles;

  bool insideBounds(const Eigen::Vector3d& p, double margin = 0.0) const {
    return (p.array() >= bounds_min.array() + margin).all() &&
           (p.array() <= bounds_max.array() - margin).all();
  }

  // Signed distance from p to the nearest obstacle surface (+inf in an empty world).
  double distanceToObstacles(const Eigen::Vector3d& p) const {
    double best = std::numeric_limits<double>::infinity();
    for (const Obstacle& o : obstacles) best = std::min(best, o.signedDistance(p));
    return best;
  }
};

}  // namespace cosim
