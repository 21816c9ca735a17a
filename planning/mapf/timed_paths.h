#pragma once
// Turns a MAPF solution into timed metric paths for execution by (ground) robots: agent i is at
// the centre of paths[i][k] at time k * step_duration, moving at constant speed in between
// (every step, also a diagonal one, takes step_duration: seed 004 §3.6), and stays at its last
// waypoint afterwards.
#include <Eigen/Core>
#include <vector>

#include "planning/mapf/mapf_problem.h"

namespace cosim {

struct TimedWaypoint {
  double t = 0.0;            // seconds from the common start
  Eigen::Vector3d position;  // metres
};
using TimedPath = std::vector<TimedWaypoint>;

// grid gives the metric frame (origin, cell size); z: height of the robots' reference point.
std::vector<TimedPath> timedMetricPaths(const OccupancyGrid& grid,
                                        const std::vector<MapfPath>& paths, double step_duration,
                                        double z = 0.0);

}  // namespace cosim
