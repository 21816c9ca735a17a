#pragma once
// Collision prediction with several moving obstacles, seed 000 §4.2.1: every node of the
// planned path is stamped with the robot's arrival time and occupies its cell from the previous
// node's time to the next node's (a diagonal step also occupies its two orthogonal side cells);
// each visible obstacle's motion is predicted and stamped the same way; a cell where the two
// overlap in time is a collision point.
#include <vector>

#include "planning/navigation/navigation_world.h"

namespace cosim {

enum class ObstaclePrediction {
  // The seed's (and [41]'s) assumption: constant direction and speed from the current state.
  ConstantVelocity,
  // The obstacles' deterministic trajectories are known to the robot (e.g. announced schedules).
  Trajectory,
};

class CollisionPredictor {
 public:
  // Sees what a robot at `robot` sees at time t (obstacles overlapping its field of view).
  CollisionPredictor(const NavigationWorld& world, ObstaclePrediction mode, const Cell& robot,
                     int sight, double t);

  bool anyVisible() const { return !visible_.empty(); }
  // Collision points of `path` (robot's cell first, leaving it at time t); the robot's own cell
  // is never one (it cannot be planned around).
  std::vector<Cell> collisionPoints(const std::vector<Cell>& path) const;
  // True if the move a -> b starting at t (a == b: waiting one time unit) cannot hit a visible
  // obstacle. Trajectory: checked against the known positions. ConstantVelocity: checked
  // against every motion the obstacle could make at its speed, so that a turn the prediction did
  // not foresee cannot cause a hit (our addition to the seed, which lost robots this way).
  bool stepSafe(const Cell& a, const Cell& b) const;

 private:
  Eigen::Vector2d predicted(std::size_t i, double s) const;  // obstacle i, s after t

  const NavigationWorld& world_;
  ObstaclePrediction mode_;
  double t_, horizon_;
  std::vector<std::size_t> visible_;
  std::vector<Eigen::Vector2d> position_, velocity_;  // at t, per visible obstacle
};

// Where a robot at `at` goes when waiting there is unsafe (an obstacle's track runs through its
// cell): the legal neighbour on the true map, not in `excluded`, that stepSafe admits and that is
// nearest to `toward`. Returns false if there is none (the robot then has to wait).
bool evasiveStep(const NavigationWorld& world, const CollisionPredictor& predictor, const Cell& at,
                 const Cell& toward, bool conditional_diagonal, const std::vector<Cell>& excluded,
                 Cell& out);

}  // namespace cosim
