#pragma once
// A given reference from samples (t, x, y, z, yaw): the clamped cubic spline through them, at
// rest at both ends, as polynomial pieces (one per interval between samples) flown like any
// piecewise-polynomial reference (control/piecewise_polynomial_reference.h: timescale, offset,
// held ends).
//
// How the derivatives are formed: each coordinate (x, y, z, yaw) is interpolated by the cubic
// spline with clamped ends (first derivative 0 at the first and the last sample: the vehicle
// starts in hover and holds the last point at rest), whose second derivatives M_i at the samples
// solve the tridiagonal system of Burden & Faires, Numerical Analysis (9th ed., 2011), section
// 3.5, Algorithm 3.5 ("clamped cubic spline"):
//   2 h_0 M_0 + h_0 M_1 = 6 ((y_1 - y_0) / h_0 - y'_0),
//   h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1}
//       = 6 ((y_{i+1} - y_i) / h_i - (y_i - y_{i-1}) / h_{i-1}),
//   h_{n-1} M_{n-1} + 2 h_{n-1} M_n = 6 (y'_n - (y_n - y_{n-1}) / h_{n-1}),
// solved by the Thomas algorithm (the matrix is strictly diagonally dominant). Velocity and
// acceleration are then continuous and exact derivatives of the spline; jerk is constant on each
// interval (it jumps at the samples) and snap is zero. A reference that needs smooth jerk and
// snap feed-forward is better given as polynomial pieces.
//
// Yaw is unwrapped first (each sample's yaw moved by whole turns to within half a turn of the
// one before), so that a heading passing +-pi turns the short way.
#include <Eigen/Core>
#include <vector>

#include "control/piecewise_polynomial_reference.h"

namespace cosim {

struct ReferenceSample {
  double t = 0.0;  // s
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double yaw = 0.0;  // rad
};

// The spline's pieces; the first sample's time is the reference's start. Throws
// std::invalid_argument for fewer than two samples or times that do not increase.
std::vector<ReferencePiece> clampedCubicSplinePieces(const std::vector<ReferenceSample>& samples);

// A piecewise-polynomial reference whose pieces are that spline. It adds no state: copied as a
// PiecewisePolynomialReference it is the same reference.
class SampledReference : public PiecewisePolynomialReference {
 public:
  explicit SampledReference(const std::vector<ReferenceSample>& samples,
                            const ReferencePlacement& placement = {})
      : PiecewisePolynomialReference(clampedCubicSplinePieces(samples), placement) {}
};

}  // namespace cosim
