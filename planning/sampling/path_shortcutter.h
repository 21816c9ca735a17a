#pragma once
// Optional post-step of the sampling planners: greedy shortcutting. From each kept waypoint the
// path jumps to the farthest later waypoint that is in straight-line sight, so the result is never
// longer than the input and stays collision-free (every new segment is checked).
#include <functional>

#include "planning/path.h"

namespace cosim {

using SegmentTest = std::function<bool(const Eigen::Vector3d&, const Eigen::Vector3d&)>;

Path shortcutPath(const Path& path, const SegmentTest& segment_free);

}  // namespace cosim
