#pragma once
// A timed path for a ground robot: the robot's reference point is at points[k] at times[k] and
// moves at constant velocity in between; it waits at the first point before times[0] and stays
// at the last point afterwards (a MAPF plan executed step by step, seed 004 §1.4, or a path
// timed at a cruise speed). Points can be appended while it is followed (a navigator deciding
// step by step).
#include <vector>

#include "control/ground_controller.h"

namespace cosim {

class GroundTimedPath {
 public:
  // Throws std::invalid_argument if a time is not after the previous one (equal is allowed: a
  // jump, e.g. a duplicated point) or the path is empty when sampled.
  void append(double t, const Eigen::Vector2d& p);
  // Timed at constant `speed` along the polyline from t0.
  static GroundTimedPath atConstantSpeed(const std::vector<Eigen::Vector2d>& points, double speed,
                                         double t0 = 0.0);

  // Smooths the corners: the reference becomes the average of the timed path over
  // [t - h, t + h], which turns every velocity jump dv into a constant acceleration dv / 2h for
  // 2h seconds (linear segments with parabolic blends, J. J. Craig, "Introduction to Robotics",
  // §7.3). h = v / a keeps a reversal at speed v within acceleration a. Corners are cut by at
  // most |dv| h / 8, and the reference passes each timed point at its time when the path runs
  // straight through it.
  void setSmoothing(double half_width);

  // Position and velocity at time t; yaw is left 0 (the caller sets the heading to hold).
  PlanarReference sample(double t) const;
  bool empty() const { return times_.empty(); }
  double endTime() const { return times_.empty() ? 0.0 : times_.back(); }
  // When the (smoothed) reference comes to rest at the last point.
  double finishTime() const { return endTime() + h_; }
  double smoothing() const { return h_; }
  const std::vector<double>& times() const { return times_; }
  const std::vector<Eigen::Vector2d>& points() const { return points_; }

 private:
  std::vector<double> times_;
  std::vector<Eigen::Vector2d> points_;
  double h_ = 0.0;

  Eigen::Vector2d positionAt(double t) const;  // the unsmoothed timed path
  // Integral of the unsmoothed path over [a, b].
  Eigen::Vector2d integral(double a, double b) const;
};

}  // namespace cosim
