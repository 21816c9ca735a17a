#include "planning/mapf/timed_paths.h"

#include "core/input_error.h"

namespace cosim {

std::vector<TimedPath> timedMetricPaths(const OccupancyGrid& grid,
                                        const std::vector<MapfPath>& paths, double step_duration,
                                        double z) {
  if (!(step_duration > 0.0)) throw InputError("", "step_duration", "must be positive");
  std::vector<TimedPath> timed;
  timed.reserve(paths.size());
  for (const MapfPath& path : paths) {
    TimedPath p;
    p.reserve(path.size());
    for (std::size_t k = 0; k < path.size(); ++k) {
      Eigen::Vector3d position = grid.cellCenter(path[k]);
      position.z() = z;
      p.push_back({static_cast<double>(k) * step_duration, position});
    }
    timed.push_back(std::move(p));
  }
  return timed;
}

}  // namespace cosim
