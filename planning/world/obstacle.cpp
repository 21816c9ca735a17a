#include "planning/world/obstacle.h"

#include <algorithm>
#include <cmath>

namespace cosim {

namespace {

// Point p expressed in the obstacle frame (translated to its centre, rotated by -yaw).
Eigen::Vector3d toLocal(const Obstacle& o, const Eigen::Vector3d& p) {
  const double yaw = o.yaw_deg * M_PI / 180.0;
  const double c = std::cos(yaw), s = std::sin(yaw);
  const Eigen::Vector3d d = p - o.pos;
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y(), d.z()};
}

// Signed distance of a point q (in the box frame) to a box of half extents h.
double boxSignedDistance(const Eigen::Vector3d& q, const Eigen::Vector3d& h) {
  const Eigen::Vector3d d = q.cwiseAbs() - h;
  const double outside = d.cwiseMax(0.0).norm();
  const double inside = std::min(d.maxCoeff(), 0.0);
  return outside + inside;
}

}  // namespace

double Obstacle::signedDistance(const Eigen::Vector3d& p) const {
  switch (type) {
    case ObstacleType::Sphere:
      return (p - pos).norm() - radius;
    case ObstacleType::Box:
      return boxSignedDistance(toLocal(*this, p), 0.5 * size);
    case ObstacleType::Cylinder: {
      // Distance to a finite cylinder: combine the radial and axial excess like a 2D box.
      const Eigen::Vector3d q = p - pos;
      const double radial = std::hypot(q.x(), q.y()) - radius;
      const double axial = std::abs(q.z()) - 0.5 * height;
      const double outside = std::hypot(std::max(radial, 0.0), std::max(axial, 0.0));
      const double inside = std::min(std::max(radial, axial), 0.0);
      return outside + inside;
    }
  }
  return 0.0;
}

void Obstacle::boundingBox(double inflation, Eigen::Vector3d& lo, Eigen::Vector3d& hi) const {
  Eigen::Vector3d half = Eigen::Vector3d::Zero();
  switch (type) {
    case ObstacleType::Sphere:
      half.setConstant(radius);
      break;
    case ObstacleType::Cylinder:
      half = {radius, radius, 0.5 * height};
      break;
    case ObstacleType::Box: {
      const double yaw = yaw_deg * M_PI / 180.0;
      const double c = std::abs(std::cos(yaw)), s = std::abs(std::sin(yaw));
      half = {0.5 * (c * size.x() + s * size.y()), 0.5 * (s * size.x() + c * size.y()),
              0.5 * size.z()};
      break;
    }
  }
  half.array() += inflation;
  lo = pos - half;
  hi = pos + half;
}

const char* obstacleTypeName(ObstacleType type) {
  switch (type) {
    case ObstacleType::Box:
      return "box";
    case ObstacleType::Cylinder:
      return "cylinder";
    case ObstacleType::Sphere:
      return "sphere";
  }
  return "?";
}

}  // namespace cosim
