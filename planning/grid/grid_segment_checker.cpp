#include "planning/grid/grid_segment_checker.h"

namespace cosim {

GridSegmentChecker::GridSegmentChecker(const World& world, const OccupancyGrid& grid,
                                       double inflation, bool planar, double plane_z)
    : near_(OccupancyGrid::fromWorld(world, grid.cellSize(), inflation, planar, plane_z,
                                     OccupancyGrid::Blocking::AnyPoint)),
      // The floor is the grid's own business (cells too close to it are blocked, and a segment
      // between two centres high enough stays high enough), so no bounds clearance here.
      world_(world, inflation, 0.0, planar) {}

bool GridSegmentChecker::pointsClear(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  ++exact_checks_;
  return world_.segmentFree(a, b);
}

}  // namespace cosim
