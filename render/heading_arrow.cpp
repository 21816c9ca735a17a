#include "render/heading_arrow.h"

namespace cosim {

std::optional<Eigen::Vector3d> headingArrowDirection(const Eigen::Vector3d& velocity) {
  const double speed = velocity.norm();
  if (!(speed >= kStillSpeed)) return std::nullopt;
  return Eigen::Vector3d(velocity / speed);
}

}  // namespace cosim
