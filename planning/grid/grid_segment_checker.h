#pragma once
// Continuous checks of grid edges against the inflated obstacles, for grids whose cells are
// judged at their centres only (OccupancyGrid::Blocking::Exact). Between two free centres a
// segment may still clip an inflated obstacle (a thin wall between cells, a corner), so every
// move and line of sight of a search is checked against the real geometry. Most edges are far
// from obstacles: a cell none of whose points is within the inflation of an obstacle (the
// conservative AnyPoint test) is "far", and a segment whose supercover touches only far cells is
// clear without an exact test; the others are tested exactly (CollisionWorld::segmentFree, the
// Minkowski sum of obstacle and ball).
#include <Eigen/Core>

#include "planning/grid/occupancy_grid.h"
#include "planning/sampling/collision_world.h"

namespace cosim {

class GridSegmentChecker {
 public:
  // `grid` is the centre-judged grid of `world` (the near cells get its cell size, origin and
  // layers); plane_z and planar as for OccupancyGrid::fromWorld.
  GridSegmentChecker(const World& world, const OccupancyGrid& grid, double inflation, bool planar,
                     double plane_z);
  // The search walks the near cells itself (GridSearchSpace::moveAllowed, lineOfSight) and asks
  // for the exact test only when a segment touches one.

  // 1 where some point of the cell may lie within the inflation of an obstacle.
  const std::uint8_t* nearData() const { return near_.data(); }
  // The segment [a, b] stays farther than the inflation from every obstacle (and inside the
  // bounds): the exact test, for segments that touch a near cell.
  bool pointsClear(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  // Exact segment tests made so far (the far-cells shortcut does not count).
  double exactChecks() const { return exact_checks_; }

 private:
  OccupancyGrid near_;
  CollisionWorld world_;
  mutable double exact_checks_ = 0;
};

}  // namespace cosim
