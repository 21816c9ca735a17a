#pragma once
// A static obstacle of the world, as the scenario file describes it. This is the one source of
// truth for geometry: the MuJoCo model, the planners' grids and collision checks, and the
// clearance metric are all derived from these values.
#include <Eigen/Core>

namespace cosim {

enum class ObstacleType { Box, Cylinder, Sphere };

struct Obstacle {
  ObstacleType type = ObstacleType::Box;
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();   // centre, metres
  Eigen::Vector3d size = Eigen::Vector3d::Zero();  // box: full edge lengths
  double radius = 0.0;                             // cylinder, sphere
  double height = 0.0;                             // cylinder: full height along z
  double yaw_deg = 0.0;                            // rotation about z (boxes, cylinders)

  // Signed Euclidean distance from p to the obstacle surface: negative inside.
  double signedDistance(const Eigen::Vector3d& p) const;

  // Axis-aligned bounding box of the obstacle grown by `inflation` metres.
  void boundingBox(double inflation, Eigen::Vector3d& lo, Eigen::Vector3d& hi) const;
};

const char* obstacleTypeName(ObstacleType type);

}  // namespace cosim
