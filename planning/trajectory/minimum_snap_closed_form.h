#pragma once
// The minimum-snap polynomial through fixed waypoints for given segment durations, in closed
// form (Richter, Bry and Roy 2013, "Polynomial trajectory planning for aggressive quadrotor flight
// in dense indoor environments", Sec. 3.2: the unconstrained QP in the end derivatives).
//
// Each piece is degree 7 and is fixed by its position, velocity, acceleration and jerk at both
// ends. Waypoint positions are fixed; the vehicle starts and ends at rest (velocity, acceleration,
// jerk zero); velocity, acceleration and jerk at interior waypoints are shared by the two pieces
// (continuity up to jerk) and chosen to minimise the total snap cost. At that optimum snap and its
// next two derivatives are continuous as well (the Euler-Lagrange condition of the problem).
// The free derivatives solve a block-tridiagonal linear system (one 3x3 block per interior
// waypoint, the same matrix for x, y and z), so a cost evaluation is O(number of segments).
#include <Eigen/Core>
#include <vector>

#include "planning/trajectory/piecewise_polynomial_trajectory.h"
#include "planning/trajectory/polynomial_basis.h"

namespace cosim {

class MinimumSnapClosedForm {
 public:
  // At least two waypoints; consecutive waypoints must differ (callers drop duplicates).
  explicit MinimumSnapClosedForm(std::vector<Eigen::Vector3d> waypoints);

  std::size_t segmentCount() const { return waypoints_.size() - 1; }
  const std::vector<Eigen::Vector3d>& waypoints() const { return waypoints_; }

  // The minimal snap cost (sum over x, y, z of int |snap|^2 dt) for these durations (all > 0);
  // with `gradient`, also dJ/dT_i, from the envelope theorem (the free derivatives are optimal,
  // so only the explicit dependence of each piece's cost on its duration counts).
  double cost(const std::vector<double>& durations, std::vector<double>* gradient = nullptr) const;

  // The optimal trajectory for these durations.
  PiecewisePolynomialTrajectory trajectory(const std::vector<double>& durations) const;

 private:
  // Rows: position, velocity, acceleration, jerk; columns: x, y, z.
  using EndDerivatives = Eigen::Matrix<double, 4, 3>;
  // Each piece's cost matrix in its end derivatives; checks the durations.
  std::vector<polynomial_basis::Matrix8d> pieceCosts(const std::vector<double>& durations) const;
  // The end derivatives at every waypoint of the optimal fit, given the pieces' cost matrices.
  std::vector<EndDerivatives> solve(const std::vector<polynomial_basis::Matrix8d>& H) const;

  std::vector<Eigen::Vector3d> waypoints_;
};

}  // namespace cosim
