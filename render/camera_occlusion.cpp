#include "render/camera_occlusion.h"

#include <algorithm>
#include <limits>

namespace cosim {

double firstObstacleHit(const std::vector<Obstacle>& obstacles, const Eigen::Vector3d& from,
                        const Eigen::Vector3d& to, double clearance) {
  const double length = (to - from).norm();
  if (obstacles.empty()) return 1.0;
  const Eigen::Vector3d dir =
      length > 0.0 ? Eigen::Vector3d((to - from) / length) : Eigen::Vector3d::UnitX();
  // Steps below a millimetre: the segment grazes a surface; that counts as touching it.
  constexpr double kTouch = 1e-3;
  constexpr int kMaxSteps = 512;
  double s = 0.0;
  for (int k = 0; k < kMaxSteps; ++k) {
    const Eigen::Vector3d p = from + s * dir;
    double d = std::numeric_limits<double>::infinity();
    for (const Obstacle& o : obstacles) d = std::min(d, o.signedDistance(p));
    d -= clearance;
    if (d < kTouch) return length > 0.0 ? s / length : 0.0;
    s += d;
    if (s >= length) return 1.0;
  }
  return length > 0.0 ? s / length : 0.0;  // still grazing after every step: call it a hit
}

bool overFloor(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
               double margin) {
  return p.x() >= lo.x() + margin && p.x() <= hi.x() - margin && p.y() >= lo.y() + margin &&
         p.y() <= hi.y() - margin;
}

}  // namespace cosim
