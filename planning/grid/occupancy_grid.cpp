#include "planning/grid/occupancy_grid.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/input_error.h"

namespace cosim {

OccupancyGrid::OccupancyGrid(int nx, int ny, int nz, double cell_size,
                             const Eigen::Vector3d& origin)
    : nx_(nx), ny_(ny), nz_(nz), cell_size_(cell_size), origin_(origin) {
  if (nx <= 0 || ny <= 0 || nz <= 0)
    throw InputError("", "grid",
                     "dimensions must be positive, got " + std::to_string(nx) + "x" +
                         std::to_string(ny) + "x" + std::to_string(nz));
  if (!(cell_size > 0.0) || !std::isfinite(cell_size))
    throw InputError("", "grid", "cell size must be positive");
  const std::int64_t n = std::int64_t(nx) * ny * nz;
  if (n > kMaxCells)
    throw InputError("", "grid",
                     std::to_string(nx) + "x" + std::to_string(ny) + "x" + std::to_string(nz) +
                         " = " + std::to_string(n) + " cells exceeds the limit of " +
                         std::to_string(kMaxCells) + " (use a coarser resolution)");
  cells_.assign(static_cast<std::size_t>(n), 0);
}

std::size_t OccupancyGrid::blockedCount() const {
  return static_cast<std::size_t>(std::count(cells_.begin(), cells_.end(), 1));
}

Cell OccupancyGrid::cellOf(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d q = (p - origin_) / cell_size_;
  return {static_cast<int>(std::floor(q.x())), static_cast<int>(std::floor(q.y())),
          nz_ == 1 ? 0 : static_cast<int>(std::floor(q.z()))};
}

OccupancyGrid OccupancyGrid::fromWorld(const World& world, double cell_size, double inflation,
                                       bool planar, double plane_z, Blocking blocking) {
  const Eigen::Vector3d extent = world.bounds_max - world.bounds_min;
  const int nx = std::max(1, static_cast<int>(std::ceil(extent.x() / cell_size - 1e-9)));
  const int ny = std::max(1, static_cast<int>(std::ceil(extent.y() / cell_size - 1e-9)));
  const int nz =
      planar ? 1 : std::max(1, static_cast<int>(std::ceil(extent.z() / cell_size - 1e-9)));
  Eigen::Vector3d origin = world.bounds_min;
  if (planar) origin.z() = plane_z - 0.5 * cell_size;  // the layer's centres sit at plane_z
  OccupancyGrid grid(nx, ny, nz, cell_size, origin);

  // Half the diagonal of a cell (of a square in the planar case): the farthest any point of
  // the cell is from its centre.
  const double half_diagonal = 0.5 * cell_size * std::sqrt(planar ? 2.0 : 3.0);
  const bool any_point = blocking == Blocking::AnyPoint;
  const bool closed = any_point || blocking == Blocking::Exact;  // distance == reach blocks
  const double reach = inflation + (any_point ? half_diagonal : 0.0);
  for (const Obstacle& o : world.obstacles) {
    Eigen::Vector3d lo, hi;
    o.boundingBox(reach, lo, hi);
    const Cell a = grid.cellOf(lo), b = grid.cellOf(hi);
    for (int z = std::max(0, a.z); z <= std::min(nz - 1, b.z); ++z)
      for (int y = std::max(0, a.y); y <= std::min(ny - 1, b.y); ++y)
        for (int x = std::max(0, a.x); x <= std::min(nx - 1, b.x); ++x) {
          const Eigen::Vector3d c = grid.cellCenter({x, y, z});
          const double d = o.signedDistance(c);
          if (closed ? d <= reach : d < reach) grid.setBlocked(x, y, z, true);
        }
  }
  // The last cell along an axis may stick out of the bounds (the extent is rarely a multiple of
  // the cell size); with exact occupancy its centre must lie inside them.
  if (blocking == Blocking::Exact)
    for (int z = 0; z < nz; ++z)
      for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
          Eigen::Vector3d c = grid.cellCenter({x, y, z});
          if (planar) c.z() = std::clamp(c.z(), world.bounds_min.z(), world.bounds_max.z());
          if (!world.insideBounds(c)) grid.setBlocked(x, y, z, true);
        }
  // The floor (the bottom of the bounds) is physical: cells whose centre is closer than
  // `inflation` to it are blocked, so paths keep the vehicle off the ground. The other faces of
  // the bounds only delimit the flight area (the grid already ends there).
  if (!planar)
    for (int z = 0; z < nz; ++z) {
      if (grid.cellCenter({0, 0, z}).z() - world.bounds_min.z() >= inflation) break;
      for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) grid.setBlocked(x, y, z, true);
    }
  return grid;
}

}  // namespace cosim
