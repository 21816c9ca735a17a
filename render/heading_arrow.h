#pragma once
// The arrow drawn at each vehicle shows where it is going: its velocity's direction, not its
// yaw (a quadrotor flies sideways as well as forward, and a yaw arrow looked wrong in the chase
// view). A vehicle nearly at rest has no arrow.
#include <Eigen/Core>
#include <optional>

namespace cosim {

// m/s: below this a vehicle counts as still (a hovering quadrotor's drift is a few cm/s).
constexpr double kStillSpeed = 0.1;

// The unit direction of `velocity`, or nothing when its speed is below kStillSpeed.
std::optional<Eigen::Vector3d> headingArrowDirection(const Eigen::Vector3d& velocity);

}  // namespace cosim
