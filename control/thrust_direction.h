#pragma once
// The two steps every thrust-vectoring controller here shares (geometric, INDI, DSL PID): a
// commanded thrust vector kept within a tilt limit, and the attitude that points the body z axis
// along it with the body x axis as close to the reference heading as that allows (Lee, Leok and
// McClamroch 2010, Sec. IV: b3 = A / |A|, b2 = b3 x b1c / |b3 x b1c|, b1 = b2 x b3; Mellinger and
// Kumar 2011 eq. 6 in the same form).
#include <Eigen/Core>

namespace cosim {

// `A` (world, per unit mass or in N) with its vertical part floored at `min_z` and its horizontal
// part shrunk so that it leans at most `max_tilt_deg` from vertical: height is kept first.
Eigen::Vector3d limitTilt(Eigen::Vector3d A, double min_z, double max_tilt_deg);

// Body to world: z along `thrust` (any non-zero vector), x towards the heading `yaw` (rad).
Eigen::Matrix3d attitudeAlong(const Eigen::Vector3d& thrust, double yaw);

}  // namespace cosim
