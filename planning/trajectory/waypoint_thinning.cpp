#include "planning/trajectory/waypoint_thinning.h"

#include "planning/world/segment_distance.h"

namespace cosim {

std::vector<Eigen::Vector3d> dropDuplicateWaypoints(const std::vector<Eigen::Vector3d>& waypoints,
                                                    double min_distance) {
  std::vector<Eigen::Vector3d> out;
  for (const Eigen::Vector3d& p : waypoints)
    if (out.empty() || (p - out.back()).norm() >= min_distance) out.push_back(p);
  if (!waypoints.empty() && out.size() > 1 && (out.back() - waypoints.back()).norm() > 0.0)
    out.back() = waypoints.back();  // the goal is exact even if a near-duplicate preceded it
  return out;
}

std::vector<Eigen::Vector3d> dropCollinearWaypoints(const std::vector<Eigen::Vector3d>& waypoints,
                                                    double tolerance) {
  if (waypoints.size() <= 2) return waypoints;
  std::vector<Eigen::Vector3d> out{waypoints.front()};
  std::size_t anchor = 0;
  for (std::size_t next = 2; next < waypoints.size(); ++next) {
    // Can the waypoints anchor+1 .. next-1 all be replaced by the line anchor -> next?
    bool straight = true;
    for (std::size_t k = anchor + 1; k < next && straight; ++k)
      straight = distanceToSegment(waypoints[k], waypoints[anchor], waypoints[next]) <= tolerance;
    if (!straight) {
      anchor = next - 1;
      out.push_back(waypoints[anchor]);
    }
  }
  out.push_back(waypoints.back());
  return out;
}

std::vector<Eigen::Vector3d> shortcutWaypoints(const std::vector<Eigen::Vector3d>& waypoints,
                                               const InflatedWorld& world) {
  if (waypoints.size() <= 2) return waypoints;
  std::vector<Eigen::Vector3d> out{waypoints.front()};
  std::size_t anchor = 0;
  while (anchor + 1 < waypoints.size()) {
    std::size_t reach = anchor + 1;  // the next waypoint is kept even if its segment is blocked
    while (reach + 1 < waypoints.size() &&
           world.segmentClear(waypoints[anchor], waypoints[reach + 1]))
      ++reach;
    out.push_back(waypoints[reach]);
    anchor = reach;
  }
  return out;
}

}  // namespace cosim
