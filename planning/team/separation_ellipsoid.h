#pragma once
// How close two quadrotors may fly: an axis-aligned ellipsoid around one vehicle that the other's
// centre must stay out of, taller than wide because of the downwash below a rotor (Preiss, Hoenig,
// Ayanian and Sukhatme, "Downwash-aware trajectory planning for large quadrotor teams", IROS 2017;
// Hoenig, Preiss, Kumar, Sukhatme and Ayanian, "Trajectory planning for quadrotor swarms", T-RO
// 2018). Their per-robot ellipsoid for a Crazyflie has radii 0.12, 0.12, 0.3 m; two such ellipsoids
// touch when the centres are 0.24 m apart side by side or 0.6 m one above the other, so the
// pairwise ellipsoid here (radius, height) is twice theirs.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace cosim {

struct SeparationEllipsoid {
  double radius = 0.24;  // m, horizontal semi-axis
  double height = 0.6;   // m, vertical semi-axis

  // || diag(1/r, 1/r, 1/h) (a - b) ||: 1 on the ellipsoid's surface, below 1 inside.
  double distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    const Eigen::Vector3d d = a - b;
    return std::sqrt((d.x() * d.x() + d.y() * d.y()) / (radius * radius) +
                     d.z() * d.z() / (height * height));
  }
  // The ellipsoid two vehicles of different sizes keep: the larger of each semi-axis.
  static SeparationEllipsoid between(const SeparationEllipsoid& a, const SeparationEllipsoid& b) {
    return {std::max(a.radius, b.radius), std::max(a.height, b.height)};
  }
};

}  // namespace cosim
