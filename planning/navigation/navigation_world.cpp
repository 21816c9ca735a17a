#include "planning/navigation/navigation_world.h"

#include <cmath>
#include <cstdlib>

#include "core/input_error.h"

namespace cosim {

NavigationWorld::NavigationWorld(OccupancyGrid grid, std::vector<MovingObstacle> obstacles)
    : grid_(std::move(grid)), obstacles_(std::move(obstacles)) {
  if (grid_.is3D()) throw InputError("", "navigation world", "the grid must be 2D");
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    // Every segment the obstacle travels (sampled every 1/8 cell) must be clear of static
    // obstacles; a loop also travels from its last waypoint back to its first.
    const std::vector<Cell>& w = obstacles_[i].waypoints();
    const bool loop = obstacles_[i].mode() == MovingObstacle::Mode::Loop;
    const std::size_t segments = w.size() == 1 ? 1 : (loop ? w.size() : w.size() - 1);
    for (std::size_t k = 0; k < segments; ++k) {
      const Cell& a = w[k];
      const Cell& b = w[(k + 1) % w.size()];
      const int samples = 8 * (std::abs(b.x - a.x) + std::abs(b.y - a.y));
      for (int j = 0; j <= samples; ++j) {
        const double f = samples > 0 ? static_cast<double>(j) / samples : 0.0;
        const int x = static_cast<int>(std::lround(a.x + f * (b.x - a.x)));
        const int y = static_cast<int>(std::lround(a.y + f * (b.y - a.y)));
        if (grid_.blocked(x, y))
          throw InputError("", "moving obstacle " + std::to_string(i),
                           "its way from (" + std::to_string(a.x) + ", " + std::to_string(a.y) +
                               ") crosses (" + std::to_string(x) + ", " + std::to_string(y) +
                               "), which is outside the grid or in a static obstacle");
      }
    }
  }
}

Eigen::Vector3d NavigationWorld::obstacleCentre(std::size_t i, double t) const {
  const Eigen::Vector2d p = obstacleCell(i, t);
  return grid_.origin() + grid_.cellSize() * Eigen::Vector3d(p.x() + 0.5, p.y() + 0.5, 0.5);
}

std::vector<std::size_t> NavigationWorld::visibleObstacles(const Cell& robot, int sight,
                                                           double t) const {
  std::vector<std::size_t> seen;
  for (std::size_t i = 0; i < obstacles_.size(); ++i)
    for (const Cell& c : obstacles_[i].cellsAt(t))
      if (inView(robot, c, sight)) {
        seen.push_back(i);
        break;
      }
  return seen;
}

bool NavigationWorld::robotHitsObstacle(const Cell& a, const Cell& b, double t, double duration,
                                        std::size_t* which) const {
  constexpr int kSamples = 16;
  const Eigen::Vector2d pa(a.x, a.y), pb(b.x, b.y);
  for (int k = 0; k <= kSamples; ++k) {
    const double f = static_cast<double>(k) / kSamples;
    const Eigen::Vector2d robot = pa + f * (pb - pa);
    for (std::size_t i = 0; i < obstacles_.size(); ++i)
      if (unitSquaresOverlap(robot, obstacles_[i].positionAt(t + f * duration))) {
        if (which) *which = i;
        return true;
      }
  }
  return false;
}

}  // namespace cosim
