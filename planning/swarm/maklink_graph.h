#pragma once
// The MAKLINK free-space graph (M. K. Habib, H. Asama, "Efficient method to generate collision
// free paths for an autonomous mobile robot based on new free space structuring approach",
// IROS 1991), as seed 002 (part B) builds it:
//  1. candidate free lines join each grown obstacle's vertices to other obstacles' vertices and
//     (perpendicularly) to the boundary walls; lines crossing a grown obstacle are dropped;
//  2. redundant lines are removed: shortest lines are kept first and a line may not cross a kept
//     one; then a line is removed when the free-space angles at both its ends stay <= 180 degrees
//     without it, so the regions between the lines stay convex and become as large as possible;
//  3. the midpoints of the remaining lines are the graph's vertices; two of them (or the start
//     or goal) are joined when they see each other without crossing an obstacle or another line,
//     i.e. when they border the same region.
// Dijkstra over it gives the seed's first, midpoint-to-midpoint path.
#include <Eigen/Core>
#include <vector>

#include "core/stop_token.h"
#include "planning/swarm/planar_obstacles.h"

namespace cosim {

struct MaklinkLine {
  Eigen::Vector2d a, b;
  Eigen::Vector2d midpoint() const { return 0.5 * (a + b); }
  // The point at normalised offset h in [0, 1] (the seed's P_i(h_i)): a at 0, b at 1.
  Eigen::Vector2d at(double h) const { return a + h * (b - a); }
};

struct MaklinkRoute {
  bool found = false;
  std::vector<int> lines;  // the free lines crossed, in order from start to goal (d of them)
  double length = 0.0;     // start -> midpoints -> goal
};

class MaklinkGraph {
 public:
  // bounds_min/max: the free area's walls (already shrunk by the vehicle's inflation).
  // Construction is quadratic in the obstacles' vertices (and more); with a deadline it stops
  // when the deadline expires and complete() is false.
  MaklinkGraph(std::vector<ConvexPolygon> obstacles, const Eigen::Vector2d& bounds_min,
               const Eigen::Vector2d& bounds_max, const StopToken* deadline = nullptr);

  bool complete() const { return complete_; }
  const std::vector<MaklinkLine>& lines() const { return lines_; }
  const std::vector<ConvexPolygon>& obstacles() const { return obstacles_; }
  // The free space: inside the walls and outside every grown obstacle.
  bool pointFree(const Eigen::Vector2d& p) const;
  // The segment stays in free space (may touch obstacle boundaries).
  bool segmentFree(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;

  // Dijkstra from start to goal over the midpoints.
  MaklinkRoute shortestRoute(const Eigen::Vector2d& start, const Eigen::Vector2d& goal) const;

 private:
  bool crossesNoLine(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
  std::vector<ConvexPolygon> obstacles_;
  Eigen::Vector2d lo_, hi_;
  std::vector<MaklinkLine> lines_;
  bool complete_ = true;
};

}  // namespace cosim
