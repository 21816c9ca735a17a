#include "planning/trajectory/trajectory_limits.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/input_error.h"

namespace cosim {
namespace {

// Calls f(sample) at `samples_per_piece` evenly spaced times of every piece, ends included.
template <typename F>
void forEachSample(const PiecewisePolynomialTrajectory& trajectory, int samples_per_piece, F f) {
  const int n = std::max(2, samples_per_piece);
  for (std::size_t i = 0; i < trajectory.pieces().size(); ++i) {
    const double T = trajectory.pieces()[i].duration;
    for (int k = 0; k < n; ++k) f(trajectory.samplePiece(i, T * k / (n - 1)));
  }
}

}  // namespace

void TrajectoryLimits::validate() const {
  const auto require_positive = [](double value, const char* name) {
    if (!(value > 0.0) || std::isnan(value))
      throw InputError("trajectory", name,
                       "must be > 0 (got " + std::to_string(value) + "): no trajectory can move");
  };
  require_positive(max_speed, "max_speed");
  require_positive(max_acceleration, "max_acceleration");
  if (!std::isfinite(max_speed) || !std::isfinite(max_acceleration))
    throw InputError("trajectory", "max_speed/max_acceleration", "must be finite");
  if (!(gravity >= 0.0) || !std::isfinite(gravity))
    throw InputError("trajectory", "gravity", "must be finite and >= 0");
  if (!(max_thrust_accel > gravity))
    throw InputError("trajectory", "max_thrust_accel",
                     "must exceed gravity (" + std::to_string(gravity) +
                         " m/s^2), or the vehicle cannot even hover (got " +
                         std::to_string(max_thrust_accel) + ")");
}

TrajectoryPeaks samplePeaks(const PiecewisePolynomialTrajectory& trajectory, double gravity,
                            int samples_per_piece) {
  TrajectoryPeaks peaks;
  const Eigen::Vector3d g(0.0, 0.0, gravity);
  forEachSample(trajectory, samples_per_piece, [&](const TrajectorySample& s) {
    peaks.speed = std::max(peaks.speed, s.velocity.norm());
    peaks.acceleration = std::max(peaks.acceleration, s.acceleration.norm());
    peaks.thrust_accel = std::max(peaks.thrust_accel, (s.acceleration + g).norm());
  });
  return peaks;
}

double timeScaleForLimits(const PiecewisePolynomialTrajectory& trajectory,
                          const TrajectoryLimits& limits, int samples_per_piece) {
  const double g = limits.gravity;
  const double F = limits.max_thrust_accel;
  double scale = 0.0;
  forEachSample(trajectory, samples_per_piece, [&](const TrajectorySample& s) {
    scale = std::max(scale, s.velocity.norm() / limits.max_speed);
    const double a2 = s.acceleration.squaredNorm();
    scale = std::max(scale, std::sqrt(std::sqrt(a2) / limits.max_acceleration));
    if (std::isfinite(F) && a2 > 0.0) {
      // u^2 |a|^2 + 2 u g a_z + g^2 <= F^2: the larger root, in the form without cancellation.
      const double az = s.acceleration.z();
      const double u_max =
          (F * F - g * g) / (g * az + std::sqrt(g * g * az * az + a2 * (F * F - g * g)));
      scale = std::max(scale, 1.0 / std::sqrt(u_max));
    }
  });
  return scale;
}

}  // namespace cosim
