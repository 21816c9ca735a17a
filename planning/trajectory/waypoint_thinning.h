#pragma once
// Fewer, better-placed waypoints before fitting a trajectory. A grid planner returns one waypoint
// per cell; a polynomial forced through every one of them wiggles and is slow (every waypoint is a
// segment whose duration must be allocated). Seed 003 flew such paths raw.
#include <Eigen/Core>
#include <vector>

#include "planning/trajectory/inflated_world.h"

namespace cosim {

// Consecutive waypoints closer than `min_distance` merged into the first of them (the last
// waypoint is always kept).
std::vector<Eigen::Vector3d> dropDuplicateWaypoints(const std::vector<Eigen::Vector3d>& waypoints,
                                                    double min_distance);

// Interior waypoints dropped while every waypoint between the last kept one and the next
// candidate lies within `tolerance` metres of the straight line joining them (straight runs of
// grid cells collapse to their ends).
std::vector<Eigen::Vector3d> dropCollinearWaypoints(const std::vector<Eigen::Vector3d>& waypoints,
                                                    double tolerance);

// String pulling: from each kept waypoint, the path jumps to the farthest following waypoint it
// can reach in a straight line clear of `world` (advancing one waypoint at a time while the line
// of sight holds), making the path any-angle. Pass a world inflated by a little more than the
// vehicle needs, so the smooth curve has room to deviate from the straight shortcuts.
std::vector<Eigen::Vector3d> shortcutWaypoints(const std::vector<Eigen::Vector3d>& waypoints,
                                               const InflatedWorld& world);

}  // namespace cosim
