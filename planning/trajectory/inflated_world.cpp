#include "planning/trajectory/inflated_world.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "planning/trajectory/polynomial_basis.h"

namespace cosim {

InflatedWorld::InflatedWorld(const World& world, double inflation,
                             const std::vector<Eigen::Vector3d>& waypoints)
    : world_(&world), inflation_(inflation), check_bounds_(Eigen::Array3d::Zero()) {
  for (const Eigen::Vector3d& p : waypoints)
    for (int k = 0; k < 3; ++k)
      if (std::abs(p[k] - waypoints.front()[k]) > 1e-9) check_bounds_[k] = 1.0;
}

double InflatedWorld::clearance(const Eigen::Vector3d& p) const {
  double c = world_->distanceToObstacles(p) - inflation_;
  for (int k = 0; k < 3; ++k) {
    if (check_bounds_[k] == 0.0) continue;
    c = std::min({c, p[k] - world_->bounds_min[k], world_->bounds_max[k] - p[k]});
  }
  return c;
}

bool InflatedWorld::inCollision(const Eigen::Vector3d& p) const {
  if (world_->distanceToObstacles(p) <= inflation_) return true;
  for (int k = 0; k < 3; ++k)
    if (check_bounds_[k] != 0.0 && (p[k] < world_->bounds_min[k] || p[k] > world_->bounds_max[k]))
      return true;
  return false;
}

bool InflatedWorld::segmentClear(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  const double length = (b - a).norm();
  double s = 0.0;  // arc length from a
  while (true) {
    const Eigen::Vector3d p = length > 0.0 ? Eigen::Vector3d(a + (b - a) * (s / length)) : a;
    if (inCollision(p)) return false;
    if (s >= length) return true;
    s = std::min(length, s + std::max(clearance(p), kTolerance));
  }
}

std::vector<InflatedWorld::Collision> InflatedWorld::collisions(
    const PiecewisePolynomialTrajectory& trajectory) const {
  std::vector<Collision> found;
  for (std::size_t i = 0; i < trajectory.pieces().size(); ++i) {
    const PolynomialPiece& piece = trajectory.pieces()[i];
    // |dq/ds| <= sum_k k |c_k| on [0, 1] per axis: a bound on the speed in s, so the point moves
    // at most that much per unit of s.
    Eigen::Vector3d bound = Eigen::Vector3d::Zero();
    for (int k = 1; k < PolynomialPiece::kCoefficients; ++k)
      bound += k * piece.coefficients.row(k).cwiseAbs().transpose();
    const double speed_in_s = std::max(bound.norm(), 1e-12);
    double s = 0.0;
    while (true) {
      const Eigen::Vector3d p = polynomial_basis::evaluate(piece.coefficients, 0, s);
      if (inCollision(p)) {
        found.push_back({i, p});
        break;
      }
      if (s >= 1.0) break;
      s = std::min(1.0, s + std::max(clearance(p), kTolerance) / speed_in_s);
    }
  }
  return found;
}

}  // namespace cosim
