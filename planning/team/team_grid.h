#pragma once
// The 3D grid a quadrotor team is planned on: box cells, as wide as they are deep and taller than
// wide, whose pitch on each axis is sqrt(2) times that semi-axis of the separation ellipsoid
// (scaled by the ellipsoidal distance the plan keeps). In coordinates scaled by the ellipsoid the
// grid is cubic with pitch sqrt(2) separations, the spacing team_trajectories.h relies on: two
// agents moving between adjacent cells along the grid's axes (6-connected) stay at least one
// separation apart at every instant of the lock-step plan interpolated linearly.
//
// A cell is free when the three axis-parallel segments through its centre, each one pitch long,
// keep `inflation` (vehicle radius + margin) clear of every obstacle and of the bounds: every
// 6-connected move runs along such segments, so a grid path flown straight keeps the vehicle's
// body clear.
#include <Eigen/Core>

#include "planning/grid/occupancy_grid.h"
#include "planning/world/world.h"

namespace cosim {

class TeamGrid {
 public:
  // Throws InputError (place "planner.separation") if the world's bounds hold no cell or the grid
  // exceeds the MAPF planners' cell limit.
  static TeamGrid over(const World& world, const Eigen::Vector3d& pitch, double inflation);
  // The same with `anchor` at a cell's centre (the grid then starts within a cell of the bounds).
  static TeamGrid over(const World& world, const Eigen::Vector3d& pitch, double inflation,
                       const Eigen::Vector3d& anchor);

  // The occupancy in cell units (cell size 1, origin 0): what a MapfInstance holds.
  const OccupancyGrid& occupancy() const { return occupancy_; }
  const Eigen::Vector3d& pitch() const { return pitch_; }
  Eigen::Vector3d centre(const Cell& c) const {
    return origin_ + pitch_.cwiseProduct(Eigen::Vector3d(c.x + 0.5, c.y + 0.5, c.z + 0.5));
  }
  // The cell containing p (may be outside the grid).
  Cell cellOf(const Eigen::Vector3d& p) const;

 private:
  static TeamGrid build(const World& world, const Eigen::Vector3d& pitch, double inflation,
                        const Eigen::Vector3d& origin, const Eigen::Vector3i& n);

  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();  // the grid is centred in the bounds
  Eigen::Vector3d pitch_ = Eigen::Vector3d::Ones();
  OccupancyGrid occupancy_;
};

}  // namespace cosim
