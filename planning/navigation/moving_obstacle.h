#pragma once
// A moving obstacle of seed 000 (§4.2.3): one cell in size, moving at constant speed along
// straight segments. Unlike the seed's obstacles (which turned at random when blocked), its
// trajectory is deterministic, given by waypoint cells, so a run can be repeated and a
// physics simulation can drive the same obstacle (e.g. a MuJoCo mocap body) from positionAt(t).
#include <Eigen/Core>
#include <vector>

#include "planning/grid/occupancy_grid.h"

namespace cosim {

class MovingObstacle {
 public:
  enum class Mode {
    BackAndForth,  // w0 -> ... -> wn -> ... -> w0 -> ...
    Loop,          // w0 -> ... -> wn -> w0 -> ...
  };
  // waypoints: cells (at least one; one = standing still); speed in cells per time unit (the
  // robot moves at 1); phase: time already travelled along the trajectory at t = 0.
  MovingObstacle(std::vector<Cell> waypoints, double speed, Mode mode = Mode::BackAndForth,
                 double phase = 0.0);

  // Centre at time t in continuous cell coordinates (cell (x, y) has its centre at (x, y)).
  Eigen::Vector2d positionAt(double t) const;
  Eigen::Vector2d velocityAt(double t) const;  // cells per time unit
  double speed() const { return speed_; }
  const std::vector<Cell>& waypoints() const { return waypoints_; }
  Mode mode() const { return mode_; }
  // The cells the obstacle overlaps at time t: 1, 2 (one coordinate between cells) or 4.
  std::vector<Cell> cellsAt(double t) const;

 private:
  // Position along the closed route (the back-and-forth route is the waypoints there and back).
  Eigen::Vector2d along(double s) const;

  std::vector<Cell> waypoints_;
  std::vector<Eigen::Vector2d> route_;  // closed polyline (first point repeated at the end)
  std::vector<double> cumulative_;      // arc length at each route vertex
  Mode mode_;
  double speed_ = 0.0, phase_ = 0.0;
};

}  // namespace cosim
