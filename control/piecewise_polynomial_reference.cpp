#include "control/piecewise_polynomial_reference.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cosim {

namespace {

constexpr int kOrders = 5;  // position to snap

// kFalling.f[k][i] = i (i-1) ... (i-k+1): d^k/dtau^k of tau^i is that times tau^(i-k).
struct FallingFactorials {
  double f[kOrders][ReferencePiece::kCoefficients];
};
constexpr FallingFactorials fallingFactorials() {
  FallingFactorials t{};
  for (int k = 0; k < kOrders; ++k)
    for (int i = 0; i < ReferencePiece::kCoefficients; ++i) {
      double f = 1.0;
      for (int j = 0; j < k; ++j) f *= i - j;
      t.f[k][i] = f;
    }
  return t;
}
constexpr FallingFactorials kFalling = fallingFactorials();

// Row k: the k-th derivative of p(tau) = sum_i c_i tau^i, for x, y, z, yaw, each by Horner's
// rule on the differentiated coefficients (this runs at every control step).
Eigen::Matrix<double, kOrders, 4> derivatives(const ReferencePiece::Coefficients& c, double tau) {
  constexpr int n = ReferencePiece::kCoefficients;
  Eigen::Matrix<double, kOrders, 4> d;
  for (int k = 0; k < kOrders; ++k) {
    Eigen::RowVector4d row = kFalling.f[k][n - 1] * c.row(n - 1);
    for (int i = n - 2; i >= k; --i) row = row * tau + kFalling.f[k][i] * c.row(i);
    d.row(k) = row;
  }
  return d;
}

}  // namespace

PiecewisePolynomialReference::PiecewisePolynomialReference(std::vector<ReferencePiece> pieces,
                                                           const ReferencePlacement& placement)
    : pieces_(std::move(pieces)), placement_(placement) {
  if (pieces_.empty()) throw std::invalid_argument("a reference needs at least one piece");
  if (!std::isfinite(placement_.timescale) || !(placement_.timescale > 0.0) ||
      !placement_.offset.allFinite())
    throw std::invalid_argument("a reference's timescale must be > 0 and its offset finite");
  starts_.reserve(pieces_.size());
  for (const ReferencePiece& p : pieces_) {
    if (!std::isfinite(p.duration) || !(p.duration > 0.0))
      throw std::invalid_argument("a reference piece's duration must be > 0");
    starts_.push_back(file_duration_);
    file_duration_ += p.duration;
  }
}

FlatReference PiecewisePolynomialReference::reference(double t, const VehicleState&) {
  finished_ = finished_ || t >= duration();
  return at(t);
}

FlatReference PiecewisePolynomialReference::evaluate(double tau) const {
  std::size_t piece = 0;
  double local = 0.0;
  const bool held = tau <= 0.0 || tau >= file_duration_;
  if (tau >= file_duration_) {
    piece = pieces_.size() - 1;
    local = pieces_.back().duration;
  } else if (tau > 0.0) {
    piece = static_cast<std::size_t>(std::upper_bound(starts_.begin(), starts_.end(), tau) -
                                     starts_.begin()) -
            1;
    local = std::min(tau - starts_[piece], pieces_[piece].duration);
  }
  const Eigen::Matrix<double, kOrders, 4> d = derivatives(pieces_[piece].coefficients, local);
  FlatReference r;
  r.position = d.row(0).head<3>().transpose();
  r.yaw = d(0, 3);
  if (held) return r;  // at rest before the start and after the end
  r.velocity = d.row(1).head<3>().transpose();
  r.acceleration = d.row(2).head<3>().transpose();
  r.jerk = d.row(3).head<3>().transpose();
  r.snap = d.row(4).head<3>().transpose();
  r.yaw_rate = d(1, 3);
  r.yaw_acceleration = d(2, 3);
  return r;
}

FlatReference PiecewisePolynomialReference::at(double t) const {
  const double s = placement_.timescale;
  FlatReference r = evaluate(t / s);
  // d^k/dt^k p(t / s) = p^(k)(t / s) / s^k
  r.position += placement_.offset;
  r.velocity /= s;
  r.acceleration /= s * s;
  r.jerk /= s * s * s;
  r.snap /= s * s * s * s;
  r.yaw_rate /= s;
  r.yaw_acceleration /= s * s;
  return r;
}

PiecewisePolynomialReference PiecewisePolynomialReference::placed(
    const ReferencePlacement& placement) const {
  return PiecewisePolynomialReference(pieces_, placement);
}

std::vector<Eigen::Vector3d> PiecewisePolynomialReference::sampledPath(std::size_t max_points,
                                                                       double min_step) const {
  const double T = duration();
  const double intervals =
      std::clamp(std::floor(T / std::max(min_step, 1e-9)), 1.0,
                 static_cast<double>(std::max<std::size_t>(max_points, 2) - 1));
  const auto n = static_cast<std::size_t>(intervals);
  std::vector<Eigen::Vector3d> path;
  path.reserve(n + 1);
  for (std::size_t i = 0; i <= n; ++i)
    path.push_back(at(T * static_cast<double>(i) / static_cast<double>(n)).position);
  return path;
}

}  // namespace cosim
