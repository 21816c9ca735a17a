#pragma once
// The picture `cosim plan` writes beside path.csv: the planned path in its world, from above
// (x, y) and from the side (along the longer horizontal axis of the trip, z), with the start and
// the goal. Obstacles are drawn as their footprints from above and as their extent along the
// axis and in height from the side (only those within kPlanSideViewReach of the path: projected
// onto one plane, every obstacle of a forest would hide the path). gnuplot (render/gnuplot.h).
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "planning/world/world.h"

namespace cosim {

// m: the side view shows the obstacles whose footprint comes this close to the path's.
constexpr double kPlanSideViewReach = 2.0;

// Writes out_base.png and out_base.svg (each complete or not at all). `path` may be empty (no
// path found): the world, start and goal are drawn all the same. Throws std::runtime_error if
// gnuplot fails.
void writePlanFigure(const World& world, const std::vector<Eigen::Vector3d>& path,
                     const Eigen::Vector3d& start, const Eigen::Vector3d& goal,
                     const std::string& title, const std::filesystem::path& out_base);

}  // namespace cosim
