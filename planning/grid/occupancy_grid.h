#pragma once
// A 2D (nz = 1) or 3D occupancy grid of cubic cells. Cell (x, y, z) covers
// [origin + (x, y, z) * cell_size, origin + (x+1, y+1, z+1) * cell_size). For MovingAI maps
// x = column, y = row, cell_size = 1, origin = 0.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "planning/world/world.h"

namespace cosim {

struct Cell {
  int x = 0, y = 0, z = 0;
  bool operator==(const Cell& o) const { return x == o.x && y == o.y && z == o.z; }
  bool operator!=(const Cell& o) const { return !(*this == o); }
};

class OccupancyGrid {
 public:
  // Largest grid we agree to allocate (cells); bigger requests are an input error, checked
  // before any allocation.
  static constexpr std::int64_t kMaxCells = std::int64_t(1) << 28;

  OccupancyGrid() = default;
  // Throws InputError if a dimension is not positive or the grid exceeds kMaxCells.
  OccupancyGrid(int nx, int ny, int nz = 1, double cell_size = 1.0,
                const Eigen::Vector3d& origin = Eigen::Vector3d::Zero());

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int nz() const { return nz_; }
  bool is3D() const { return nz_ > 1; }
  double cellSize() const { return cell_size_; }
  const Eigen::Vector3d& origin() const { return origin_; }
  std::size_t cellCount() const { return cells_.size(); }

  bool inside(int x, int y, int z = 0) const {
    return x >= 0 && y >= 0 && z >= 0 && x < nx_ && y < ny_ && z < nz_;
  }
  bool inside(const Cell& c) const { return inside(c.x, c.y, c.z); }
  std::size_t index(int x, int y, int z = 0) const {
    return (static_cast<std::size_t>(z) * ny_ + y) * nx_ + x;
  }
  std::size_t index(const Cell& c) const { return index(c.x, c.y, c.z); }
  Cell cellAt(std::size_t index) const {
    const int x = static_cast<int>(index % nx_);
    const int y = static_cast<int>((index / nx_) % ny_);
    const int z = static_cast<int>(index / (static_cast<std::size_t>(nx_) * ny_));
    return {x, y, z};
  }
  // Cells outside the grid count as blocked.
  bool blocked(int x, int y, int z = 0) const { return !inside(x, y, z) || cells_[index(x, y, z)]; }
  bool blocked(const Cell& c) const { return blocked(c.x, c.y, c.z); }
  bool free(const Cell& c) const { return !blocked(c); }
  void setBlocked(int x, int y, int z, bool value) { cells_[index(x, y, z)] = value ? 1 : 0; }
  void setBlocked(const Cell& c, bool value) { setBlocked(c.x, c.y, c.z, value); }
  std::size_t blockedCount() const;
  // The cells as one flat array in index() order, 1 = blocked: for search loops that read
  // neighbours by index offset without bounds checks.
  const std::uint8_t* data() const { return cells_.data(); }

  Eigen::Vector3d cellCenter(const Cell& c) const {
    return origin_ + cell_size_ * Eigen::Vector3d(c.x + 0.5, c.y + 0.5, c.z + 0.5);
  }
  // The cell containing p (may be outside the grid).
  Cell cellOf(const Eigen::Vector3d& p) const;

  // How a cell is judged against the (inflated) obstacles.
  enum class Blocking {
    // Blocked when any point of the cell could lie within `inflation` of an obstacle (centre
    // distance <= inflation + half the cell diagonal): a path through free cells keeps the
    // vehicle's volume clear of obstacles. The default.
    AnyPoint,
    // Blocked only when the cell's centre lies within `inflation` of an obstacle (strictly
    // inside it for inflation 0): seed 003's grid, whose vertices are cell centres and an
    // obstacle blocks the vertices it contains. Paths may graze obstacles.
    Centre,
    // Blocked exactly when the vehicle cannot stand at the cell's centre: the centre is within
    // `inflation` of an obstacle (distance <= inflation, as CollisionWorld::pointFree) or
    // outside the world's bounds. Edges between free centres are not implied clear: a search
    // checks them against the inflated geometry (GridSegmentChecker). With those checks a grid
    // search is complete at its resolution, where AnyPoint closes gaps narrower than a cell.
    Exact,
  };

  // Voxelises a world: cells are blocked as `blocking` says; cells closer than `inflation` to
  // the floor (the bottom of the bounds) are blocked too. planar: a one-layer grid at height
  // plane_z for ground robots.
  static OccupancyGrid fromWorld(const World& world, double cell_size, double inflation,
                                 bool planar = false, double plane_z = 0.0,
                                 Blocking blocking = Blocking::AnyPoint);

 private:
  int nx_ = 0, ny_ = 0, nz_ = 0;
  double cell_size_ = 1.0;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  std::vector<std::uint8_t> cells_;
};

}  // namespace cosim
