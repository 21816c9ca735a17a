#include "control/waypoint_reference.h"

#include <stdexcept>

namespace cosim {

WaypointReference::WaypointReference(std::vector<Eigen::Vector3d> waypoints, double yaw,
                                     double switch_radius)
    : waypoints_(std::move(waypoints)), yaw_(yaw), switch_radius_(switch_radius) {
  if (waypoints_.empty()) throw std::invalid_argument("WaypointReference needs a waypoint");
}

FlatReference WaypointReference::reference(double /*t*/, const VehicleState& state) {
  // Skip every waypoint already within reach (the vehicle may pass several in one step).
  while (index_ + 1 < waypoints_.size() &&
         (state.position - waypoints_[index_]).norm() < switch_radius_)
    ++index_;
  FlatReference ref;
  ref.position = waypoints_[index_];
  ref.yaw = yaw_;
  return ref;
}

}  // namespace cosim
