#include "planning/navigation/moving_obstacle.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"

namespace cosim {

MovingObstacle::MovingObstacle(std::vector<Cell> waypoints, double speed, Mode mode, double phase)
    : waypoints_(std::move(waypoints)), mode_(mode), speed_(speed), phase_(phase) {
  if (waypoints_.empty())
    throw InputError("", "moving obstacle", "needs at least one waypoint cell");
  if (!(speed >= 0.0) || !std::isfinite(speed))
    throw InputError("", "moving obstacle", "speed must be a finite number >= 0");
  for (const Cell& c : waypoints_) route_.emplace_back(c.x, c.y);
  if (mode == Mode::BackAndForth)
    for (int i = static_cast<int>(waypoints_.size()) - 2; i >= 0; --i)
      route_.emplace_back(waypoints_[i].x, waypoints_[i].y);
  else
    route_.emplace_back(waypoints_.front().x, waypoints_.front().y);
  cumulative_.assign(1, 0.0);
  for (std::size_t i = 1; i < route_.size(); ++i)
    cumulative_.push_back(cumulative_.back() + (route_[i] - route_[i - 1]).norm());
}

Eigen::Vector2d MovingObstacle::along(double s) const {
  const double total = cumulative_.back();
  if (total <= 0.0) return route_.front();
  s = std::fmod(s, total);
  if (s < 0.0) s += total;
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  const std::size_t i = std::min<std::size_t>(it - cumulative_.begin(), cumulative_.size() - 1);
  const double seg = cumulative_[i] - cumulative_[i - 1];
  const double f = seg > 0.0 ? (s - cumulative_[i - 1]) / seg : 0.0;
  return route_[i - 1] + f * (route_[i] - route_[i - 1]);
}

Eigen::Vector2d MovingObstacle::positionAt(double t) const {
  return along(phase_ + speed_ * t);
}

Eigen::Vector2d MovingObstacle::velocityAt(double t) const {
  // Central difference over a short arc; exact on a segment, the mean direction at a corner.
  const double h = 1e-4;
  return (positionAt(t + h) - positionAt(t)) / h;
}

std::vector<Cell> MovingObstacle::cellsAt(double t) const {
  const Eigen::Vector2d p = positionAt(t);
  // §4.2.3: off the grid points an obstacle overlaps the cells around it (2 or 4 of them).
  const double eps = 1e-9;
  const int x0 = static_cast<int>(std::floor(p.x() + eps)),
            y0 = static_cast<int>(std::floor(p.y() + eps));
  const bool fx = p.x() - x0 > eps, fy = p.y() - y0 > eps;
  std::vector<Cell> cells{{x0, y0, 0}};
  if (fx) cells.push_back({x0 + 1, y0, 0});
  if (fy) cells.push_back({x0, y0 + 1, 0});
  if (fx && fy) cells.push_back({x0 + 1, y0 + 1, 0});
  return cells;
}

}  // namespace cosim
