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

PlanarReference GroundTimedPath::sample(double t) const {
  if (times_.empty()) throw std::invalid_argument("timed path: empty");
  PlanarReference r;
  if (t < times_.front()) {
    r.position = points_.front();
    return r;
  }
  if (t >= times_.back()) {
    r.position = points_.back();
    r.final = true;
    return r;
  }
  // The segment [times_[k], times_[k + 1]) holding t.
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) - 1;
  const double dt = times_[k + 1] - times_[k];
  const double s = dt > 0 ? (t - times_[k]) / dt : 1.0;
  r.position = points_[k] + s * (points_[k + 1] - points_[k]);
  if (dt > 0) r.velocity = (points_[k + 1] - points_[k]) / dt;
  return r;
}

}  // namespace cosim
