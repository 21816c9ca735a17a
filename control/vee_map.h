#pragma once
// The vee map of SO(3): the vector w of a skew-symmetric matrix S = [w]x, read off as
// (S32, S13, S21) (Lee, Leok and McClamroch 2010, "Geometric tracking control of a quadrotor UAV
// on SE(3)", the hat and vee maps of section II). Shared by every controller with an attitude error
// on SO(3).
#include <Eigen/Core>

namespace cosim {

inline Eigen::Vector3d vee(const Eigen::Matrix3d& S) { return {S(2, 1), S(0, 2), S(1, 0)}; }

}  // namespace cosim
