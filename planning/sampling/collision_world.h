#pragma once
// The continuous collision world of the sampling planners: the scenario's obstacles grown by the
// vehicle radius plus margin, with exact point and segment tests. "Exact" means a segment is
// tested against the Minkowski sum of the obstacle and a ball (a rounded box, a rounded cylinder,
// a larger sphere) by computing the segment-to-obstacle distance, never by sampling points along
// the segment. A uniform grid over the obstacles' bounding boxes (the broad phase) keeps the cost
// of a query independent of how many obstacles are far away.
//
// Queries use a per-object scratch stamp to visit each obstacle once, so one CollisionWorld must
// not be queried from two threads at the same time (give each thread its own).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "planning/world/world.h"

namespace cosim {

class CollisionWorld {
 public:
  // inflation: vehicle radius plus margin (PlanningProblem::inflation), >= 0.
  // bounds_clearance: how far above the floor (the bottom of the bounds) valid points must stay,
  // so the vehicle's radius plus margin keeps it off the ground; ignored for planar problems.
  CollisionWorld(const World& world, double inflation, double bounds_clearance = 0.0,
                 bool planar = false);

  const Eigen::Vector3d& boundsMin() const { return bounds_min_; }
  const Eigen::Vector3d& boundsMax() const { return bounds_max_; }
  // The region valid points lie in: the bounds less the clearance above the floor.
  const Eigen::Vector3d& validMin() const { return valid_min_; }
  const Eigen::Vector3d& validMax() const { return valid_max_; }
  double inflation() const { return inflation_; }
  std::size_t obstacleCount() const { return shapes_.size(); }

  bool insideBounds(const Eigen::Vector3d& p) const;
  // p is inside the bounds and at a distance greater than `inflation` from every obstacle.
  bool pointFree(const Eigen::Vector3d& p) const;
  // Every point of the segment [a, b] is free. Both ends must be inside the bounds (the bounds
  // are convex, so the whole segment then is).
  bool segmentFree(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  // Signed distance from p to the nearest obstacle surface (not inflated); +inf with none.
  double distanceToObstacles(const Eigen::Vector3d& p) const;

 private:
  // An obstacle in the form the tests want: centre, yaw as cos/sin, half extents.
  struct Shape {
    ObstacleType type;
    Eigen::Vector3d center;
    double cos_yaw, sin_yaw;
    Eigen::Vector3d half;              // box: half edges; cylinder: (radius, radius, half height)
    double radius;                     // sphere, cylinder
    Eigen::Vector3d aabb_lo, aabb_hi;  // inflated, world frame
  };

  Eigen::Vector3d toLocal(const Shape& s, const Eigen::Vector3d& p) const;
  double signedDistance(const Shape& s, const Eigen::Vector3d& p) const;
  bool segmentHits(const Shape& s, const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  bool segmentHitsBox(const Shape& s, const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  bool segmentHitsCylinder(const Shape& s, const Eigen::Vector3d& a,
                           const Eigen::Vector3d& b) const;

  // Broad phase.
  Eigen::Vector3i cellOf(const Eigen::Vector3d& p) const;
  std::size_t cellIndex(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * dims_.y() + y) * dims_.x() + x;
  }
  // Marks obstacle i as visited by the current query; false if it already was.
  bool firstVisit(std::uint32_t i) const;
  bool cellFreeOfSegment(std::size_t cell, const Eigen::Vector3d& a,
                         const Eigen::Vector3d& b) const;

  Eigen::Vector3d bounds_min_, bounds_max_;
  Eigen::Vector3d valid_min_, valid_max_;  // the bounds less the clearance
  double inflation_;
  std::vector<Shape> shapes_;
  double cell_size_ = 1.0;
  Eigen::Vector3i dims_ = Eigen::Vector3i::Ones();
  // Compressed lists: obstacles of cell c are cell_items_[cell_start_[c] .. cell_start_[c+1]).
  std::vector<std::uint32_t> cell_start_;
  std::vector<std::uint32_t> cell_items_;
  mutable std::vector<std::uint32_t> visit_stamp_;
  mutable std::uint32_t query_id_ = 0;
};

}  // namespace cosim
