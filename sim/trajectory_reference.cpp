#include "sim/trajectory_reference.h"

namespace cosim {

FlatReference TrajectoryReference::reference(double t, const VehicleState&) {
  const TrajectorySample s = trajectory_.sample(t);  // clamped to [0, duration]
  finished_ = t >= trajectory_.duration();
  FlatReference ref;
  ref.position = s.position;
  ref.velocity = s.velocity;
  ref.acceleration = s.acceleration;
  ref.jerk = s.jerk;
  ref.snap = s.snap;
  ref.yaw = yaw_;
  return ref;
}

}  // namespace cosim
