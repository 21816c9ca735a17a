#include "sim/trajectory_mode.h"

namespace cosim {

const char* trajectoryModeName(TrajectoryMode mode) {
  return choiceName(kTrajectoryModeNames, mode);
}

std::optional<TrajectoryMode> trajectoryModeNamed(const std::string& name) {
  return choiceNamed(kTrajectoryModeNames, name);
}

}  // namespace cosim
