#pragma once
// The dynamic limits a reference trajectory must respect, and the uniform time scaling that
// makes a trajectory respect them. Limits are checked at sample points (a fixed number per
// piece), so between samples a peak may exceed a limit by a small fraction.
#include <limits>

#include "planning/trajectory/piecewise_polynomial_trajectory.h"

namespace cosim {

struct TrajectoryLimits {
  double max_speed = 3.0;         // m/s, |v|
  double max_acceleration = 5.0;  // m/s^2, |a|
  // m/s^2: the thrust per unit mass |a + g e3| the airframe can produce (its maximum thrust over
  // its mass, minus a margin for control). Infinity for vehicles that do not fly.
  double max_thrust_accel = std::numeric_limits<double>::infinity();
  double gravity = 9.81;  // m/s^2

  // Throws InputError (file "trajectory", place the parameter) for limits no trajectory meets.
  void validate() const;
};

// Largest values found at the sample points.
struct TrajectoryPeaks {
  double speed = 0.0;
  double acceleration = 0.0;
  double thrust_accel = 0.0;  // |a + g e3|
};

TrajectoryPeaks samplePeaks(const PiecewisePolynomialTrajectory& trajectory, double gravity,
                            int samples_per_piece);

// The factor s by which all durations must be multiplied so that, at the sample points, the
// trajectory meets every limit with at least one of them reached exactly (s > 1 slows it down,
// s < 1 speeds it up). Velocity scales by 1/s and acceleration by 1/s^2, so the speed and
// acceleration limits give s directly; the thrust limit |a / s^2 + g e3| <= F is a quadratic in
// u = 1/s^2 whose larger root bounds u. Returns 0 for a trajectory that does not move.
double timeScaleForLimits(const PiecewisePolynomialTrajectory& trajectory,
                          const TrajectoryLimits& limits, int samples_per_piece);

}  // namespace cosim
