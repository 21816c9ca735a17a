#pragma once
// The world's obstacles cut by a horizontal plane, as convex polygons grown by the vehicle's
// inflation: what seed 002's MAKLINK planner sees ("the boundary of each obstacle is grown so
// that the robot does not collide with it"; heights are ignored). Boxes become rotated
// rectangles (half sizes + inflation: a superset of the exact rounded grown box); cylinders and
// spheres become regular polygons circumscribing their grown circular sections.
#include <Eigen/Core>
#include <vector>

#include "planning/world/world.h"

namespace cosim {

struct ConvexPolygon {
  std::vector<Eigen::Vector2d> vertices;  // counter-clockwise
};

// Obstacles whose grown volume meets the plane z = plane_z. sides: polygon sides for round
// obstacles (>= 3).
std::vector<ConvexPolygon> planarObstacles(const World& world, double plane_z, double inflation,
                                           int sides);

// True if the segment a-b passes through the polygon's interior (touching its boundary, running
// along an edge or ending at a vertex is allowed).
bool segmentEntersPolygon(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                          const ConvexPolygon& polygon);
// True if p lies strictly inside the polygon.
bool pointInsidePolygon(const Eigen::Vector2d& p, const ConvexPolygon& polygon);
// True if the segments cross at a point interior to both (shared endpoints do not count).
bool segmentsCrossProperly(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                           const Eigen::Vector2d& c, const Eigen::Vector2d& d);

}  // namespace cosim
