#pragma once
// The vee map of so(3): the vector w of a skew-symmetric matrix S = [w]x (the inverse of the hat
// map), read from its lower triangle; applied to R_d^T R - R^T R_d it gives the attitude error of
// Lee, Leok and McClamroch 2010 (eq. 10, up to their factor 1/2).
#include <Eigen/Core>

namespace cosim {

inline Eigen::Vector3d vee(const Eigen::Matrix3d& S) {
  return {S(2, 1), S(0, 2), S(1, 0)};
}

}  // namespace cosim
