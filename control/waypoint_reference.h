#pragma once
// Seed 003's waypoint following (its section 4.2): the position set-point is the current
// waypoint, and it jumps to the next one once the vehicle is within `switch_radius` (0.2 m) of
// it. No smoothing, no velocity profile: the baseline the minimum-snap trajectories improve on.
#include <vector>

#include "control/reference_source.h"

namespace cosim {

class WaypointReference : public ReferenceSource {
 public:
  WaypointReference(std::vector<Eigen::Vector3d> waypoints, double yaw, double switch_radius = 0.2);
  FlatReference reference(double t, const VehicleState& state) override;
  bool atFinalSetpoint() const override { return index_ + 1 >= waypoints_.size(); }
  std::size_t currentIndex() const { return index_; }

 private:
  std::vector<Eigen::Vector3d> waypoints_;
  double yaw_;
  double switch_radius_;
  std::size_t index_ = 0;
};

}  // namespace cosim
