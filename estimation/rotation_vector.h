#pragma once
// The capitalised exponential and logarithmic maps between rotation vectors and unit quaternions,
// q = Exp(theta u) = [cos(theta/2), u sin(theta/2)] and its inverse Log (Solà, "Quaternion
// kinematics for the error-state Kalman filter", arXiv:1711.02508, 2017, Sec. 3), the chart in
// which the filter's attitude error and the attitude sensor's noise live. Near zero both use
// Taylor series, so a rotation of 1e-12 rad stays exact instead of dividing 0 by 0.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace cosim {

// Exp: the unit quaternion of the rotation by |phi| about phi / |phi|.
inline Eigen::Quaterniond quaternionFromRotationVector(const Eigen::Vector3d& phi) {
  const double theta2 = phi.squaredNorm();
  const double theta = std::sqrt(theta2);
  double w, s;  // s = sin(theta/2) / theta
  if (theta < 1e-4) {
    // Series to theta^4: the truncation error is below 1e-20, under double rounding.
    w = 1.0 - theta2 / 8.0 + theta2 * theta2 / 384.0;
    s = 0.5 - theta2 / 48.0 + theta2 * theta2 / 3840.0;
  } else {
    w = std::cos(0.5 * theta);
    s = std::sin(0.5 * theta) / theta;
  }
  return Eigen::Quaterniond(w, s * phi.x(), s * phi.y(), s * phi.z());
}

// Log: the rotation vector (angle in [0, pi]) of a unit quaternion; q and -q give the same.
inline Eigen::Vector3d rotationVectorFromQuaternion(const Eigen::Quaterniond& q) {
  const double sign = q.w() < 0.0 ? -1.0 : 1.0;  // the shorter of the two ways round
  const Eigen::Vector3d v = sign * q.vec();
  const double w = sign * q.w();
  const double n = v.norm();
  if (n < 1e-8) {
    // theta = 2 atan(n / w) = 2 n / w (1 - n^2 / (3 w^2)) + O(n^5).
    return (2.0 / w) * (1.0 - n * n / (3.0 * w * w)) * v;
  }
  return (2.0 * std::atan2(n, w) / n) * v;
}

}  // namespace cosim
