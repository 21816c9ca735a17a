#include "planning/navigation/collision_prediction.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "planning/grid/grid_planner.h"

namespace cosim {

namespace {
struct Occupancy {
  int x, y;
  double from, to;
};
constexpr double kSampleStep = 0.1;  // prediction sampling, in time units
}  // namespace

CollisionPredictor::CollisionPredictor(const NavigationWorld& world, ObstaclePrediction mode,
                                       const Cell& robot, int sight, double t)
    : world_(world),
      mode_(mode),
      t_(t),
      horizon_(sight),
      visible_(world.visibleObstacles(robot, sight, t)) {
  for (std::size_t i : visible_) {
    position_.push_back(world.obstacleCell(i, t));
    velocity_.push_back(world.obstacles()[i].velocityAt(t));
  }
}

Eigen::Vector2d CollisionPredictor::predicted(std::size_t k, double s) const {
  if (mode_ == ObstaclePrediction::Trajectory) return world_.obstacleCell(visible_[k], t_ + s);
  return position_[k] + s * velocity_[k];
}

std::vector<Cell> CollisionPredictor::collisionPoints(const std::vector<Cell>& path) const {
  std::vector<Cell> points;
  if (visible_.empty() || path.size() < 2) return points;
  // Arrival times and occupancy intervals of the robot's path.
  std::vector<double> arrival(path.size(), 0.0);
  for (std::size_t i = 1; i < path.size(); ++i) {
    const int dx = path[i].x - path[i - 1].x, dy = path[i].y - path[i - 1].y;
    arrival[i] = arrival[i - 1] + ((dx != 0 && dy != 0) ? std::sqrt(2.0) : 1.0);
  }
  std::vector<Occupancy> robot;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double from = arrival[i - 1];
    const double to = i + 1 < path.size() ? arrival[i + 1] : arrival[i] + 1.0;
    robot.push_back({path[i].x, path[i].y, from, to});
    if (path[i].x != path[i - 1].x && path[i].y != path[i - 1].y) {
      robot.push_back({path[i].x, path[i - 1].y, from, arrival[i]});
      robot.push_back({path[i - 1].x, path[i].y, from, arrival[i]});
    }
  }
  // The seed stamps the whole local path; we predict at most `sight` time units ahead: beyond
  // the view a prediction is guesswork (an obstacle may turn), and the robot re-plans every step.
  // Stamping further made the robots wait for conflicts twenty steps away.
  const double horizon = std::min(arrival.back() + 1.0, horizon_);
  auto add = [&](int x, int y) {
    if (x == path[0].x && y == path[0].y) return;
    for (const Cell& c : points)
      if (c.x == x && c.y == y) return;
    points.push_back({x, y, 0});
  };
  for (std::size_t k = 0; k < visible_.size(); ++k)
    for (double s = 0.0; s <= horizon + 1e-9; s += kSampleStep) {
      const Eigen::Vector2d q = predicted(k, s);
      // The cells a unit square at q overlaps (1, 2 or 4, as the seed's partial positions).
      const int x0 = static_cast<int>(std::floor(q.x() + 1e-6)),
                y0 = static_cast<int>(std::floor(q.y() + 1e-6));
      const int x1 = q.x() - x0 > 1e-6 ? x0 + 1 : x0, y1 = q.y() - y0 > 1e-6 ? y0 + 1 : y0;
      for (const Occupancy& o : robot)
        if (o.x >= x0 && o.x <= x1 && o.y >= y0 && o.y <= y1 && s >= o.from - kSampleStep &&
            s <= o.to + kSampleStep)
          add(o.x, o.y);
    }
  return points;
}

bool CollisionPredictor::stepSafe(const Cell& a, const Cell& b) const {
  const bool wait = a.x == b.x && a.y == b.y;
  const double duration = wait ? 1.0 : ((a.x != b.x && a.y != b.y) ? std::sqrt(2.0) : 1.0);
  constexpr int kSamples = 16;
  const Eigen::Vector2d pa(a.x, a.y), pb(b.x, b.y);
  for (std::size_t k = 0; k < visible_.size(); ++k) {
    const double reach = world_.obstacles()[visible_[k]].speed();
    for (int j = 0; j <= kSamples; ++j) {
      const double f = static_cast<double>(j) / kSamples, s = f * duration;
      const Eigen::Vector2d r = pa + f * (pb - pa);
      if (mode_ == ObstaclePrediction::Trajectory) {
        if (unitSquaresOverlap(r, predicted(k, s))) return false;
      } else {
        // Anywhere within reach * s of where it is now (Chebyshev distance <= Euclidean).
        const Eigen::Vector2d d = (r - position_[k]).cwiseAbs();
        if (std::max(d.x(), d.y()) < 1.0 + reach * s - 1e-6) return false;
      }
    }
  }
  return true;
}

bool evasiveStep(const NavigationWorld& world, const CollisionPredictor& predictor, const Cell& at,
                 const Cell& toward, bool conditional_diagonal, const std::vector<Cell>& excluded,
                 Cell& out) {
  double best = std::numeric_limits<double>::infinity();
  for (const GridStep& s : gridSteps(GridMoves{8, !conditional_diagonal}, false)) {
    const Cell c{at.x + s.dx, at.y + s.dy, 0};
    bool skip =
        !gridStepAllowed(world.grid(), at, s, !conditional_diagonal) || !predictor.stepSafe(at, c);
    for (const Cell& e : excluded) skip = skip || (e.x == c.x && e.y == c.y);
    const double d = std::hypot(c.x - toward.x, c.y - toward.y);
    if (!skip && d < best) {
      best = d;
      out = c;
    }
  }
  return best < std::numeric_limits<double>::infinity();
}

}  // namespace cosim
