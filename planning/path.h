#pragma once
// A geometric path: an ordered list of waypoints in metres (ground robots: z = 0).
#include <Eigen/Core>
#include <vector>

namespace cosim {

struct Path {
  std::vector<Eigen::Vector3d> waypoints;

  bool empty() const { return waypoints.empty(); }
  std::size_t size() const { return waypoints.size(); }

  // Sum of the Euclidean lengths of the segments.
  double length() const {
    double total = 0.0;
    for (std::size_t i = 1; i < waypoints.size(); ++i)
      total += (waypoints[i] - waypoints[i - 1]).norm();
    return total;
  }
};

}  // namespace cosim
