#include "control/thrust_direction.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace cosim {

Eigen::Vector3d limitTilt(Eigen::Vector3d A, double min_z, double max_tilt_deg) {
  A.z() = std::max(A.z(), min_z);
  const double max_h = A.z() * std::tan(max_tilt_deg * M_PI / 180.0);
  const double h = A.head<2>().norm();
  if (h > max_h) A.head<2>() *= max_h / h;
  return A;
}

Eigen::Matrix3d attitudeAlong(const Eigen::Vector3d& thrust, double yaw) {
  const Eigen::Vector3d b3 = thrust.normalized();
  const Eigen::Vector3d b1c(std::cos(yaw), std::sin(yaw), 0.0);
  const Eigen::Vector3d b2 = b3.cross(b1c).normalized();
  Eigen::Matrix3d R;
  R << b2.cross(b3), b2, b3;
  return R;
}

}  // namespace cosim
