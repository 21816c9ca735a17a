#include "planning/team/team_grid.h"

#include <cmath>

#include "core/input_error.h"
#include "planning/mapf/mapf_problem.h"

namespace cosim {

namespace {

// Samples per half segment: the distance to the obstacles changes by at most the distance moved
// (it is 1-Lipschitz), so a sample clear by inflation + half the spacing clears its neighbourhood.
constexpr int kSamplesPerHalfSegment = 4;

bool crossIsClear(const World& world, const Eigen::Vector3d& centre, const Eigen::Vector3d& pitch,
                  double inflation) {
  for (int axis = 0; axis < 3; ++axis) {
    const double spacing = 0.5 * pitch[axis] / kSamplesPerHalfSegment;
    for (int k = -kSamplesPerHalfSegment; k <= kSamplesPerHalfSegment; ++k) {
      Eigen::Vector3d p = centre;
      p[axis] += k * spacing;
      if (world.distanceToObstacles(p) < inflation + 0.5 * spacing) return false;
    }
  }
  return true;
}

}  // namespace

TeamGrid TeamGrid::over(const World& world, const Eigen::Vector3d& pitch, double inflation) {
  const Eigen::Vector3d extent = world.bounds_max - world.bounds_min;
  Eigen::Vector3i n;
  for (int a = 0; a < 3; ++a) n[a] = static_cast<int>(std::floor(extent[a] / pitch[a]));
  return build(world, pitch, inflation,
               world.bounds_min + 0.5 * (extent - pitch.cwiseProduct(n.cast<double>())), n);
}

TeamGrid TeamGrid::over(const World& world, const Eigen::Vector3d& pitch, double inflation,
                        const Eigen::Vector3d& anchor) {
  Eigen::Vector3d origin;
  Eigen::Vector3i n;
  for (int a = 0; a < 3; ++a) {
    // Whole cells below the anchor's, then as many as fit above.
    const double below = std::floor((anchor[a] - world.bounds_min[a]) / pitch[a] - 0.5);
    origin[a] = anchor[a] - (below + 0.5) * pitch[a];
    n[a] = static_cast<int>(std::floor((world.bounds_max[a] - origin[a]) / pitch[a]));
  }
  return build(world, pitch, inflation, origin, n);
}

TeamGrid TeamGrid::build(const World& world, const Eigen::Vector3d& pitch, double inflation,
                         const Eigen::Vector3d& origin, const Eigen::Vector3i& n) {
  if ((n.array() < 1).any())
    throw InputError("", "planner.separation",
                     "the world's bounds are smaller than one cell of the team's grid (pitch " +
                         std::to_string(pitch.x()) + " x " + std::to_string(pitch.z()) +
                         " m from the separation ellipsoid)");
  if (static_cast<long>(n.x()) * n.y() * n.z() > kMaxMapfCells)
    throw InputError("", "planner.separation",
                     "the team's grid would have more than " + std::to_string(kMaxMapfCells) +
                         " cells (a larger separation, or smaller bounds)");
  TeamGrid g;
  g.pitch_ = pitch;
  g.origin_ = origin;
  g.occupancy_ = OccupancyGrid(n.x(), n.y(), n.z());
  for (int z = 0; z < n.z(); ++z)
    for (int y = 0; y < n.y(); ++y)
      for (int x = 0; x < n.x(); ++x) {
        const Eigen::Vector3d c = g.centre({x, y, z});
        g.occupancy_.setBlocked(
            x, y, z,
            !world.insideBounds(c, inflation) || !crossIsClear(world, c, pitch, inflation));
      }
  return g;
}

Cell TeamGrid::cellOf(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d u = (p - origin_).cwiseQuotient(pitch_);
  return {static_cast<int>(std::floor(u.x())), static_cast<int>(std::floor(u.y())),
          static_cast<int>(std::floor(u.z()))};
}

}  // namespace cosim
