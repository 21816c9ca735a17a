#include "planning/trajectory/piecewise_polynomial_trajectory.h"

#include <algorithm>
#include <cmath>

#include "planning/trajectory/polynomial_basis.h"

namespace cosim {

PiecewisePolynomialTrajectory::PiecewisePolynomialTrajectory(std::vector<PolynomialPiece> pieces)
    : pieces_(std::move(pieces)) {
  computeKnots();
}

PolynomialPiece PiecewisePolynomialTrajectory::pieceFromTimeCoefficients(
    double duration, const PolynomialPiece::Coefficients& c) {
  PolynomialPiece piece;
  piece.duration = duration;
  double scale = 1.0;  // duration^k: t^k = duration^k s^k
  for (int k = 0; k < PolynomialPiece::kCoefficients; ++k) {
    piece.coefficients.row(k) = c.row(k) * scale;
    scale *= duration;
  }
  return piece;
}

void PiecewisePolynomialTrajectory::computeKnots() {
  knots_.assign(1, 0.0);
  for (const PolynomialPiece& p : pieces_) knots_.push_back(knots_.back() + p.duration);
  duration_ = knots_.back();
}

TrajectorySample PiecewisePolynomialTrajectory::sample(double t) const {
  if (pieces_.empty()) return {};
  if (t <= 0.0) {
    TrajectorySample s = samplePiece(0, 0.0);
    s.velocity = s.acceleration = s.jerk = s.snap = Eigen::Vector3d::Zero();
    return s;
  }
  if (t >= duration_) {
    TrajectorySample s = samplePiece(pieces_.size() - 1, pieces_.back().duration);
    s.velocity = s.acceleration = s.jerk = s.snap = Eigen::Vector3d::Zero();
    return s;
  }
  // The piece whose interval [knot_i, knot_{i+1}) holds t.
  const auto it = std::upper_bound(knots_.begin(), knots_.end(), t);
  const std::size_t i = std::min<std::size_t>(it - knots_.begin() - 1, pieces_.size() - 1);
  return samplePiece(i, t - knots_[i]);
}

TrajectorySample PiecewisePolynomialTrajectory::samplePiece(std::size_t piece, double tau) const {
  const PolynomialPiece& p = pieces_[piece];
  const double T = p.duration;
  const double s = T > 0.0 ? std::clamp(tau / T, 0.0, 1.0) : 0.0;
  Eigen::Vector3d d[5];
  double inv_T_power = 1.0;  // d^r/dt^r = T^-r d^r/ds^r
  for (int r = 0; r < 5; ++r) {
    d[r] = polynomial_basis::evaluate(p.coefficients, r, s) * inv_T_power;
    inv_T_power = T > 0.0 ? inv_T_power / T : 0.0;
  }
  return {d[0], d[1], d[2], d[3], d[4]};
}

double PiecewisePolynomialTrajectory::snapCost() const {
  const Eigen::Matrix<double, 8, 8>& Q = polynomial_basis::unitSnapCostMatrix();
  double cost = 0.0;
  for (const PolynomialPiece& p : pieces_) {
    if (p.duration <= 0.0) continue;
    // int_0^T |p''''(t)|^2 dt = T^-7 int_0^1 |q''''(s)|^2 ds.
    const double unit = (p.coefficients.transpose() * Q * p.coefficients).trace();
    cost += unit / std::pow(p.duration, 7);
  }
  return cost;
}

void PiecewisePolynomialTrajectory::scaleTime(double factor) {
  for (PolynomialPiece& p : pieces_) p.duration *= factor;
  computeKnots();
}

}  // namespace cosim
