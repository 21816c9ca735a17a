#pragma once
// An independent check of a returned path, sharing no code with the planners' collision tests:
// every point of every segment, sampled every `step` metres, lies inside the world's bounds and
// at least `clearance` from every obstacle surface (World::distanceToObstacles, a plain loop
// over Obstacle::signedDistance). Returns the smallest clearance met, or -inf on a point
// outside the bounds.
#include <algorithm>
#include <cmath>
#include <limits>

#include "planning/path.h"
#include "planning/world/world.h"

namespace cosim {

inline double smallestPathClearance(const World& world, const Path& path, double step = 0.005) {
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < path.waypoints.size(); ++i) {
    const Eigen::Vector3d a = path.waypoints[i - 1], b = path.waypoints[i];
    const int n = static_cast<int>((b - a).norm() / step) + 1;
    for (int k = 0; k <= n; ++k) {
      const Eigen::Vector3d p = a + (b - a) * (static_cast<double>(k) / n);
      if (!world.insideBounds(p, -1e-9)) return -std::numeric_limits<double>::infinity();
      least = std::min(least, world.distanceToObstacles(p));
    }
  }
  return least;
}

}  // namespace cosim
