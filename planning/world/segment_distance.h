#pragma once
// The distance from a point to a segment: the one formula the waypoint thinning of the planned
// path, the flight metrics (distance to the planned polyline) and the trail decimation of the
// renderer share, so that they agree to the last bit.
#include <Eigen/Core>
#include <algorithm>

namespace cosim {

// Distance from p to the closest point of the segment a-b (to a if the segment has no length).
inline double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double s = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + s * ab)).norm();
}

}  // namespace cosim
