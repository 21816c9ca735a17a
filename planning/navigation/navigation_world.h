#pragma once
// The world a navigating robot lives in (seed 000 §4.2.3, without MuJoCo): the true static grid
// (2D), moving obstacles with deterministic trajectories, and the robot's square field of view.
// Time is in robot step units: the robot moves at speed 1, so a straight step takes 1 and a
// diagonal step sqrt 2. A physics simulation can drive the same obstacles from
// obstacleCentre(i, t) (metres) and ask a Navigator for the robot's next cell.
#include <Eigen/Core>
#include <vector>

#include "planning/grid/occupancy_grid.h"
#include "planning/navigation/moving_obstacle.h"

namespace cosim {

class NavigationWorld {
 public:
  // grid must be 2D; every waypoint of every obstacle must be a free cell inside it (InputError
  // otherwise).
  NavigationWorld(OccupancyGrid grid, std::vector<MovingObstacle> obstacles = {});

  const OccupancyGrid& grid() const { return grid_; }
  const std::vector<MovingObstacle>& obstacles() const { return obstacles_; }

  // Obstacle i's centre at time t: in continuous cells, and in metres (the grid's frame, z = the
  // centre of the cell layer).
  Eigen::Vector2d obstacleCell(std::size_t i, double t) const {
    return obstacles_[i].positionAt(t);
  }
  Eigen::Vector3d obstacleCentre(std::size_t i, double t) const;

  // True if cell c is within the square field of view of half-width `sight` around `robot`.
  static bool inView(const Cell& robot, const Cell& c, int sight) {
    return std::abs(c.x - robot.x) <= sight && std::abs(c.y - robot.y) <= sight;
  }
  // Indices of the moving obstacles that overlap the field of view at time t.
  std::vector<std::size_t> visibleObstacles(const Cell& robot, int sight, double t) const;

  // True if the robot (a unit square moving in a straight line from a to b during
  // [t, t + duration]) overlaps a moving obstacle (another unit square) at some instant; a = b
  // is waiting. Sampled at 1/16 of the move. `which` receives the obstacle's index.
  bool robotHitsObstacle(const Cell& a, const Cell& b, double t, double duration,
                         std::size_t* which = nullptr) const;

 private:
  OccupancyGrid grid_;
  std::vector<MovingObstacle> obstacles_;
};

// True if two unit squares centred at p and q (cells) overlap with positive area.
inline bool unitSquaresOverlap(const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
  constexpr double kTouch = 1e-6;  // touching sides is not a collision
  return std::abs(p.x() - q.x()) < 1.0 - kTouch && std::abs(p.y() - q.y()) < 1.0 - kTouch;
}

}  // namespace cosim
