#include "sim/trajectory_mode.h"

namespace cosim {

const char* trajectoryModeName(TrajectoryMode mode) {
  return mode == TrajectoryMode::MinimumSnap ? "minimum_snap" : "waypoints";
}

std::optional<TrajectoryMode> trajectoryModeNamed(const std::string& name) {
  if (name == "waypoints") return TrajectoryMode::Waypoints;
  if (name == "minimum_snap") return TrajectoryMode::MinimumSnap;
  return std::nullopt;
}

}  // namespace cosim
