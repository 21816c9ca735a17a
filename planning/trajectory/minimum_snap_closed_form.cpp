#include "planning/trajectory/minimum_snap_closed_form.h"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

#include "planning/trajectory/polynomial_basis.h"

namespace cosim {
namespace {

using Matrix8d = polynomial_basis::Matrix8d;
using Matrix3d = Eigen::Matrix3d;

// Order of the derivative held in row j of a piece's end-derivative vector.
constexpr int kOrder[8] = {0, 1, 2, 3, 0, 1, 2, 3};

// The cost matrix of a piece of duration T in its physical end derivatives d: the snap cost is
// d^T H(T) d with H(T)_jk = H1_jk T^(a_j + a_k - 7), because the unit-interval derivatives are
// T^a_j d_j and the integral picks up T^-8 (the fourth derivative, squared) times T (the length).
// With `derivative`, dH/dT instead, entry by entry.
Matrix8d pieceCost(double T, bool derivative = false) {
  double power[9];  // power[e + 8] = T^e for e = -8..0, rather than 64 calls of pow
  power[8] = 1.0;
  for (int e = 7; e >= 0; --e) power[e] = power[e + 1] / T;
  const Matrix8d& H1 = polynomial_basis::unitEndDerivativeCost();
  Matrix8d H;
  for (int j = 0; j < 8; ++j)
    for (int k = 0; k < 8; ++k) {
      const int e = kOrder[j] + kOrder[k] - 7;
      H(j, k) = derivative ? e * H1(j, k) * power[e + 7] : H1(j, k) * power[e + 8];
    }
  return H;
}

}  // namespace

MinimumSnapClosedForm::MinimumSnapClosedForm(std::vector<Eigen::Vector3d> waypoints)
    : waypoints_(std::move(waypoints)) {
  if (waypoints_.size() < 2)
    throw std::invalid_argument("MinimumSnapClosedForm: needs at least two waypoints");
}

std::vector<MinimumSnapClosedForm::EndDerivatives> MinimumSnapClosedForm::solve(
    const std::vector<Matrix8d>& H) const {
  const std::size_t M = segmentCount();
  std::vector<EndDerivatives> w(M + 1, EndDerivatives::Zero());
  for (std::size_t i = 0; i <= M; ++i) w[i].row(0) = waypoints_[i].transpose();
  const std::size_t n = M - 1;  // interior waypoints 1..M-1 hold the unknowns
  if (n == 0) return w;

  // Normal equations K z = -b. Unknown block j (0-based) is waypoint j + 1: its velocity,
  // acceleration and jerk (rows) for x, y, z (columns). It is the end (rows 5..7) of piece j and
  // the start (rows 1..3) of piece j + 1.
  std::vector<Matrix3d> diag(n), upper(n), rhs(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Matrix8d& Hb = H[j];      // the piece ending at the waypoint
    const Matrix8d& Ha = H[j + 1];  // the piece starting at it
    diag[j] = Hb.block<3, 3>(5, 5) + Ha.block<3, 3>(1, 1);
    if (j + 1 < n) upper[j] = Ha.block<3, 3>(1, 5);
    const Eigen::RowVector3d p_prev = waypoints_[j].transpose(), p = waypoints_[j + 1].transpose(),
                             p_next = waypoints_[j + 2].transpose();
    // The fixed positions of both pieces; the end derivatives of the whole path are zero (rest).
    rhs[j] = -(Hb.block<3, 1>(5, 0) * p_prev + Hb.block<3, 1>(5, 4) * p + Ha.block<3, 1>(1, 0) * p +
               Ha.block<3, 1>(1, 4) * p_next);
  }

  // Symmetric diagonal scaling S K S (S = diag(K)^-1/2): velocity, acceleration and jerk entries
  // differ by powers of the durations, and the scaling keeps the 3x3 pivots well conditioned.
  std::vector<Eigen::Vector3d> scale(n);
  for (std::size_t j = 0; j < n; ++j) scale[j] = diag[j].diagonal().cwiseSqrt().cwiseInverse();
  for (std::size_t j = 0; j < n; ++j) {
    diag[j] = scale[j].asDiagonal() * diag[j] * scale[j].asDiagonal();
    if (j + 1 < n) upper[j] = scale[j].asDiagonal() * upper[j] * scale[j + 1].asDiagonal();
    rhs[j] = scale[j].asDiagonal() * rhs[j];
  }

  // Block Thomas algorithm: block LDL^T of the symmetric positive definite tridiagonal matrix.
  std::vector<Matrix3d> pivot_inv(n);
  pivot_inv[0] = diag[0].inverse();
  for (std::size_t j = 1; j < n; ++j) {
    const Matrix3d L = upper[j - 1].transpose() * pivot_inv[j - 1];
    pivot_inv[j] = (diag[j] - L * upper[j - 1]).inverse();
    rhs[j] -= L * rhs[j - 1];
  }
  std::vector<Matrix3d> z(n);
  z[n - 1] = pivot_inv[n - 1] * rhs[n - 1];
  for (std::size_t j = n - 1; j-- > 0;) z[j] = pivot_inv[j] * (rhs[j] - upper[j] * z[j + 1]);

  for (std::size_t j = 0; j < n; ++j) w[j + 1].bottomRows<3>() = scale[j].asDiagonal() * z[j];
  return w;
}

std::vector<polynomial_basis::Matrix8d> MinimumSnapClosedForm::pieceCosts(
    const std::vector<double>& T) const {
  if (T.size() != segmentCount())
    throw std::invalid_argument("MinimumSnapClosedForm: one duration per segment");
  std::vector<Matrix8d> H(T.size());
  for (std::size_t i = 0; i < T.size(); ++i) {
    if (!(T[i] > 0.0) || !std::isfinite(T[i]))
      throw std::invalid_argument("MinimumSnapClosedForm: durations must be finite and > 0");
    H[i] = pieceCost(T[i]);
  }
  return H;
}

double MinimumSnapClosedForm::cost(const std::vector<double>& T,
                                   std::vector<double>* gradient) const {
  const std::vector<Matrix8d> H = pieceCosts(T);
  const std::vector<EndDerivatives> w = solve(H);
  const std::size_t M = segmentCount();
  if (gradient) gradient->assign(M, 0.0);
  double J = 0.0;
  for (std::size_t i = 0; i < M; ++i) {
    Eigen::Matrix<double, 8, 3> d;
    d << w[i], w[i + 1];
    J += (d.transpose() * H[i] * d).trace();
    if (gradient) (*gradient)[i] = (d.transpose() * pieceCost(T[i], true) * d).trace();
  }
  return J;
}

PiecewisePolynomialTrajectory MinimumSnapClosedForm::trajectory(
    const std::vector<double>& T) const {
  const std::vector<EndDerivatives> w = solve(pieceCosts(T));
  std::vector<PolynomialPiece> pieces(segmentCount());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    // Unit-interval end derivatives: the r-th derivative in s is T^r times the one in t.
    Eigen::Matrix<double, 8, 3> d;
    d << w[i], w[i + 1];
    for (int j = 0; j < 8; ++j) d.row(j) *= std::pow(T[i], kOrder[j]);
    pieces[i].duration = T[i];
    pieces[i].coefficients = polynomial_basis::unitEndDerivativeMatrixInverse() * d;
  }
  return PiecewisePolynomialTrajectory(std::move(pieces));
}

}  // namespace cosim
