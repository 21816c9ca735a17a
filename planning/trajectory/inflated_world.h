#pragma once
// The world as a vehicle of radius `inflation` sees it: a point is in collision when it is within
// `inflation` of an obstacle surface (World::distanceToObstacles(p) <= inflation), or outside the
// world's bounds along an axis the path moves along (paths lying in a plane, such as a ground
// robot's on the floor, are not held to the bounds of the axis they do not use).
//
// Segments and trajectories are checked by conservative advancement: the signed distance is
// 1-Lipschitz, so from a point with clearance c the vehicle can move c metres without touching
// anything; a trajectory piece advances in time by c / (a bound on its speed). The step never
// falls below kTolerance metres, so penetrations shallower than that can be missed.
#include <Eigen/Core>
#include <vector>

#include "planning/trajectory/piecewise_polynomial_trajectory.h"
#include "planning/world/world.h"

namespace cosim {

class InflatedWorld {
 public:
  static constexpr double kTolerance = 1e-3;  // m

  // `waypoints`: the path to be checked, to tell which axes it moves along.
  InflatedWorld(const World& world, double inflation,
                const std::vector<Eigen::Vector3d>& waypoints);

  double inflation() const { return inflation_; }
  // Distance the point can move before touching an inflated obstacle or leaving the bounds;
  // <= 0 near obstacles and < 0 outside the bounds mean collision.
  double clearance(const Eigen::Vector3d& p) const;
  bool inCollision(const Eigen::Vector3d& p) const;

  // True if no point of the straight segment a-b is in collision.
  bool segmentClear(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;

  // The indices of the trajectory's pieces that come into collision (ascending), and for each the
  // first colliding point found.
  struct Collision {
    std::size_t piece = 0;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
  };
  std::vector<Collision> collisions(const PiecewisePolynomialTrajectory& trajectory) const;

 private:
  const World* world_;
  double inflation_;
  Eigen::Array3d check_bounds_;  // 1 for the axes the path moves along, 0 otherwise
};

}  // namespace cosim
