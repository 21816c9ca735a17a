#include "control/ground_timed_path.h"

#include <algorithm>
#include <stdexcept>

namespace cosim {

void GroundTimedPath::append(double t, const Eigen::Vector2d& p) {
  if (!times_.empty() && !(t >= times_.back()))
    throw std::invalid_argument("timed path: times must not decrease");
  times_.push_back(t);
  points_.push_back(p);
}

GroundTimedPath GroundTimedPath::atConstantSpeed(const std::vector<Eigen::Vector2d>& points,
                                                 double speed, double t0) {
  if (!(speed > 0)) throw std::invalid_argument("timed path: speed must be positive");
  GroundTimedPath path;
  double t = t0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) t += (points[i] - points[i - 1]).norm() / speed;
    path.append(t, points[i]);
  }
  return path;
}

void GroundTimedPath::setSmoothing(double half_width) {
  if (!(half_width >= 0)) throw std::invalid_argument("timed path: smoothing must not be negative");
  h_ = half_width;
}

Eigen::Vector2d GroundTimedPath::positionAt(double t) const {
  if (t <= times_.front()) return points_.front();
  if (t >= times_.back()) return points_.back();
  // The segment [times_[k], times_[k + 1]) holding t.
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) -
      1;
  const double dt = times_[k + 1] - times_[k];
  return dt > 0
             ? Eigen::Vector2d(points_[k] + ((t - times_[k]) / dt) * (points_[k + 1] - points_[k]))
             : points_[k + 1];
}

Eigen::Vector2d GroundTimedPath::integral(double a, double b) const {
  // The path is linear between its timed points: the trapezoid rule over them is exact.
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double t = a;
  Eigen::Vector2d p = positionAt(a);
  for (auto it = std::upper_bound(times_.begin(), times_.end(), a); it != times_.end() && *it < b;
       ++it) {
    const Eigen::Vector2d q = positionAt(*it);
    sum += 0.5 * (*it - t) * (p + q);
    t = *it;
    p = q;
  }
  return sum + 0.5 * (b - t) * (p + positionAt(b));
}

PlanarReference GroundTimedPath::sample(double t) const {
  if (times_.empty()) throw std::invalid_argument("timed path: empty");
  PlanarReference r;
  r.final = t >= finishTime();
  if (h_ > 0) {
    r.position = integral(t - h_, t + h_) / (2.0 * h_);
    r.velocity = (positionAt(t + h_) - positionAt(t - h_)) / (2.0 * h_);
    return r;
  }
  r.position = positionAt(t);
  if (t >= times_.front() && t < times_.back()) {
    const std::size_t k = static_cast<std::size_t>(
                              std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) -
                          1;
    const double dt = times_[k + 1] - times_[k];
    if (dt > 0) r.velocity = (points_[k + 1] - points_[k]) / dt;
  }
  return r;
}

}  // namespace cosim
