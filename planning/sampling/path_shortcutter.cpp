#include "planning/sampling/path_shortcutter.h"

namespace cosim {

Path shortcutPath(const Path& path, const SegmentTest& segment_free) {
  if (path.size() <= 2) return path;
  Path out;
  std::size_t i = 0;
  const std::size_t last = path.size() - 1;
  out.waypoints.push_back(path.waypoints[0]);
  while (i < last) {
    // The next waypoint always works: it is the original segment.
    std::size_t j = last;
    while (j > i + 1 && !segment_free(path.waypoints[i], path.waypoints[j])) --j;
    out.waypoints.push_back(path.waypoints[j]);
    i = j;
  }
  return out;
}

}  // namespace cosim
