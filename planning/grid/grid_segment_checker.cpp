#include "planning/grid/grid_segment_checker.h"

#include "planning/grid/grid_line_of_sight.h"

namespace cosim {

GridSegmentChecker::GridSegmentChecker(const World& world, const OccupancyGrid& grid,
                                       double inflation, bool planar, double plane_z)
    : grid_(&grid),
      near_(OccupancyGrid::fromWorld(world, grid.cellSize(), inflation, planar, plane_z,
                                     OccupancyGrid::Blocking::AnyPoint)),
      // The floor is the grid's own business (cells too close to it are blocked, and a segment
      // between two centres high enough stays high enough), so no bounds clearance here.
      world_(world, inflation, 0.0, planar) {}

bool GridSegmentChecker::centresClear(const Cell& a, const Cell& b) const {
  const bool touches_near =
      !supercoverLineOfSight(a, b, [this](int x, int y, int z) { return near_.blocked(x, y, z); });
  if (!touches_near) return true;
  return pointsClear(grid_->cellCenter(a), grid_->cellCenter(b));
}

bool GridSegmentChecker::pointsClear(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  ++exact_checks_;
  return world_.segmentFree(a, b);
}

}  // namespace cosim
