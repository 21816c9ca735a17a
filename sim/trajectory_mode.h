#pragma once
// How a quadrotor's reference is made from its planned path (the scenario's trajectory.mode):
// switching from waypoint to waypoint as it comes within the switch radius, or a minimum-snap
// polynomial through the path flown in time.
#include <optional>
#include <string>

#include "sim/declared_keys.h"

namespace cosim {

enum class TrajectoryMode { Waypoints, MinimumSnap };

inline constexpr ChoiceNames<TrajectoryMode, 2> kTrajectoryModeNames{{
    {TrajectoryMode::Waypoints, "waypoints"},
    {TrajectoryMode::MinimumSnap, "minimum_snap"},
}};

// The scenario's name of a mode ("waypoints", "minimum_snap"), also what metrics.json writes.
const char* trajectoryModeName(TrajectoryMode mode);
// The mode a scenario's name means; nullopt for any other name.
std::optional<TrajectoryMode> trajectoryModeNamed(const std::string& name);

}  // namespace cosim
