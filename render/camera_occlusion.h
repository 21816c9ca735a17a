#pragma once
// What stands between the chase camera and its vehicle, with the obstacles' own geometry (their
// exact signed distances, planning/world/obstacle.h), so the camera can be pulled in front of a
// wall instead of filming its back, and kept over the world's floor.
#include <Eigen/Core>
#include <vector>

#include "planning/world/obstacle.h"

namespace cosim {

// The fraction of the way from `from` to `to` (0..1) at which the segment first comes within
// `clearance` of an obstacle; 1 when it stays clear all the way. Sphere tracing (Hart, "Sphere
// tracing", The Visual Computer 12, 1996): each step is the distance to the nearest obstacle
// less the clearance, so no obstacle is stepped over.
double firstObstacleHit(const std::vector<Obstacle>& obstacles, const Eigen::Vector3d& from,
                        const Eigen::Vector3d& to, double clearance);

// Whether p stands over the world's floor (x and y inside [lo, hi], `margin` in from its edges).
bool overFloor(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
               double margin = 0.0);

}  // namespace cosim
