#include "planning/swarm/planar_obstacles.h"

#include <algorithm>
#include <cmath>

namespace cosim {

namespace {
constexpr double kEps = 1e-9;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

ConvexPolygon regularPolygon(const Eigen::Vector2d& centre, double radius, int sides) {
  // Circumscribing: the polygon's edges are tangent to the circle.
  const double r = radius / std::cos(M_PI / sides);
  ConvexPolygon p;
  for (int i = 0; i < sides; ++i) {
    const double a = 2.0 * M_PI * (i + 0.5) / sides;
    p.vertices.push_back(centre + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return p;
}
}  // namespace

std::vector<ConvexPolygon> planarObstacles(const World& world, double plane_z, double inflation,
                                           int sides) {
  std::vector<ConvexPolygon> out;
  for (const Obstacle& o : world.obstacles) {
    const Eigen::Vector2d c = o.pos.head<2>();
    const double dz = std::fabs(plane_z - o.pos.z());
    switch (o.type) {
      case ObstacleType::Box: {
        if (dz > o.size.z() / 2 + inflation) break;
        const double yaw = o.yaw_deg * M_PI / 180.0;
        const Eigen::Vector2d u(std::cos(yaw), std::sin(yaw)), v(-std::sin(yaw), std::cos(yaw));
        const double hx = o.size.x() / 2 + inflation, hy = o.size.y() / 2 + inflation;
        out.push_back(
            {{c - hx * u - hy * v, c + hx * u - hy * v, c + hx * u + hy * v, c - hx * u + hy * v}});
        break;
      }
      case ObstacleType::Cylinder:
        if (dz <= o.height / 2 + inflation)
          out.push_back(regularPolygon(c, o.radius + inflation, sides));
        break;
      case ObstacleType::Sphere: {
        const double grown = o.radius + inflation;
        if (dz < grown) out.push_back(regularPolygon(c, std::sqrt(grown * grown - dz * dz), sides));
        break;
      }
    }
  }
  return out;
}

bool segmentEntersPolygon(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                          const ConvexPolygon& polygon) {
  // Cyrus-Beck clipping against the open half-planes left of each counter-clockwise edge.
  const Eigen::Vector2d d = b - a;
  const double scale = 1.0 + d.norm();
  double t0 = 0.0, t1 = 1.0;
  const auto& v = polygon.vertices;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Eigen::Vector2d e = v[(i + 1) % v.size()] - v[i];
    const double len = e.norm();
    if (len == 0.0) continue;
    // Signed distance left of the edge at t: f0 + t * fd (inside: > 0).
    const double f0 = cross(e, a - v[i]) / len, fd = cross(e, d) / len;
    if (std::fabs(fd) < 1e-15) {
      if (f0 <= kEps * scale) return false;
      continue;
    }
    const double t = (kEps * scale - f0) / fd;  // where f reaches the tolerance
    if (fd > 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 >= t1) return false;
  }
  return t1 - t0 > 1e-12;
}

bool pointInsidePolygon(const Eigen::Vector2d& p, const ConvexPolygon& polygon) {
  const auto& v = polygon.vertices;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (cross(v[(i + 1) % v.size()] - v[i], p - v[i]) <= kEps) return false;
  return true;
}

bool segmentsCrossProperly(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                           const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
  const double scale = 1e-9 * (1.0 + (b - a).norm() * (d - c).norm());
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > scale && d2 < -scale) || (d1 < -scale && d2 > scale)) &&
         ((d3 > scale && d4 < -scale) || (d3 < -scale && d4 > scale));
}

}  // namespace cosim
