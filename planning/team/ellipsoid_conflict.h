#pragma once
// When two quadrotors moving in lock-step conflict: the closest ellipsoidal distance between two
// straight moves flown over the same interval with the same time law (Hoenig et al.,
// "Trajectory planning for quadrotor swarms", T-RO 2018, define the conflicts of their roadmap by
// the separation ellipsoid swept along an edge; here the sweep is synchronised, as the team's
// lock-step plan flies it). A wait is a move of length zero, so one formula gives the vertex
// conflict (two agents standing), the edge conflict (a swap, or one entering what another leaves
// at an angle) and the swept one (two moves passing each other).
//
// In coordinates scaled by the ellipsoid, S = diag(1/r, 1/r, 1/h), the relative position is
// d(u) = S (a0 - b0) + u S ((a1 - a0) - (b1 - b0)) for the common progress u in [0, 1], and the
// ellipsoidal distance is |d(u)|: a quadratic in u, smallest at u* = -d0.dd / |dd|^2 clamped to
// [0, 1].
#include <Eigen/Core>
#include <algorithm>

#include "planning/team/separation_ellipsoid.h"

namespace cosim {

inline double sweptEllipsoidDistance(const SeparationEllipsoid& e, const Eigen::Vector3d& a0,
                                     const Eigen::Vector3d& a1, const Eigen::Vector3d& b0,
                                     const Eigen::Vector3d& b1) {
  const Eigen::Vector3d scale(1.0 / e.radius, 1.0 / e.radius, 1.0 / e.height);
  const Eigen::Vector3d d0 = scale.cwiseProduct(a0 - b0);
  const Eigen::Vector3d dd = scale.cwiseProduct((a1 - a0) - (b1 - b0));
  const double dd2 = dd.squaredNorm();
  const double u = dd2 > 0.0 ? std::clamp(-d0.dot(dd) / dd2, 0.0, 1.0) : 0.0;
  return (d0 + u * dd).norm();
}

}  // namespace cosim
