#pragma once
// A reference trajectory made of polynomial pieces, one per segment, degree 7 in each axis.
// Each piece is stored in normalised time s = t / T in [0, 1] (T: the piece's duration): the
// coefficients then stay of the order of the distances flown whatever the durations, and scaling
// all durations by one factor (a uniform time scaling) leaves the coefficients unchanged.
#include <Eigen/Core>
#include <vector>

namespace cosim {

// Position and its first four time derivatives at one instant (world frame, SI units).
struct TrajectorySample {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();
  Eigen::Vector3d jerk = Eigen::Vector3d::Zero();
  Eigen::Vector3d snap = Eigen::Vector3d::Zero();
};

struct PolynomialPiece {
  static constexpr int kCoefficients = 8;  // degree 7
  using Coefficients = Eigen::Matrix<double, kCoefficients, 3>;
  double duration = 0.0;  // s
  // Row k: the coefficient of s^k for x, y, z; p(t) = sum_k c_k (t / duration)^k.
  Coefficients coefficients = Coefficients::Zero();
};

class PiecewisePolynomialTrajectory {
 public:
  PiecewisePolynomialTrajectory() = default;
  explicit PiecewisePolynomialTrajectory(std::vector<PolynomialPiece> pieces);

  // A piece from coefficients in physical local time t in [0, duration]:
  // p(t) = sum_k c_k t^k (row k of `coefficients_in_t`).
  static PolynomialPiece pieceFromTimeCoefficients(double duration,
                                                   const PolynomialPiece::Coefficients& c);

  double duration() const { return duration_; }
  bool empty() const { return pieces_.empty(); }
  const std::vector<PolynomialPiece>& pieces() const { return pieces_; }
  // Start time of each piece, and the end time last (pieces().size() + 1 entries).
  const std::vector<double>& knotTimes() const { return knots_; }

  // t is clamped to [0, duration()]: before the start and after the end the vehicle holds the
  // end point with zero derivatives (if the ends are at rest, as minimum-snap fits make them).
  TrajectorySample sample(double t) const;
  // The same, on one piece at local time tau in [0, duration of that piece].
  TrajectorySample samplePiece(std::size_t piece, double tau) const;

  // Integral of |snap|^2 over the whole trajectory, in closed form (m^2 / s^7).
  double snapCost() const;

  // All durations multiplied by `factor` (> 1 slows down): velocities scale by 1/factor,
  // accelerations by 1/factor^2, and so on; the geometric path is unchanged.
  void scaleTime(double factor);

 private:
  void computeKnots();
  std::vector<PolynomialPiece> pieces_;
  std::vector<double> knots_{0.0};
  double duration_ = 0.0;
};

}  // namespace cosim
