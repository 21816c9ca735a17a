#include "planning/sampling/state_sampler.h"

#include <Eigen/Geometry>
#include <cmath>

namespace cosim {

namespace {
// Rejection attempts before falling back to a plain uniform sample (only reached when the
// informed set is a sliver of the bounds, where the fallback costs nothing but focus).
constexpr int kMaxAttempts = 200;
}  // namespace

StateSampler::StateSampler(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, bool planar,
                           double plane_z)
    : lo_(lo), hi_(hi), planar_(planar), plane_z_(plane_z) {}

bool StateSampler::inBounds(const Eigen::Vector3d& p) const {
  return (p.array() >= lo_.array()).all() && (p.array() <= hi_.array()).all();
}

Eigen::Vector3d StateSampler::uniform(std::mt19937_64& rng) const {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Eigen::Vector3d p;
  p.x() = lo_.x() + u(rng) * (hi_.x() - lo_.x());
  p.y() = lo_.y() + u(rng) * (hi_.y() - lo_.y());
  p.z() = planar_ ? plane_z_ : lo_.z() + u(rng) * (hi_.z() - lo_.z());
  return p;
}

Eigen::Vector3d StateSampler::informed(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       double c_best, std::mt19937_64& rng) const {
  const double c_min = (b - a).norm();
  if (!(c_best > c_min) || c_min <= 0.0) return uniform(rng);
  // Radii of the prolate hyperspheroid (Gammell et al. 2014, eq. 11 ff.).
  const double r1 = 0.5 * c_best;
  const double r2 = 0.5 * std::sqrt(c_best * c_best - c_min * c_min);
  const Eigen::Vector3d centre = 0.5 * (a + b);
  const Eigen::Vector3d e1 = (b - a) / c_min;
  Eigen::Vector3d e2, e3;
  if (planar_) {
    e2 = Eigen::Vector3d(-e1.y(), e1.x(), 0.0).normalized();
    e3.setZero();
  } else {
    const Eigen::Vector3d helper =
        std::abs(e1.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    e2 = e1.cross(helper).normalized();
    e3 = e1.cross(e2);
  }
  // Sample the set whose measure is smaller and reject what falls outside the other one
  // (Gammell et al. 2014, Alg. 2 samples the ellipsoid only while it is the smaller set).
  const Eigen::Vector3d extent = hi_ - lo_;
  const double box_measure = planar_ ? extent.x() * extent.y() : extent.prod();
  const double ellipse_measure = planar_ ? M_PI * r1 * r2 : 4.0 / 3.0 * M_PI * r1 * r2 * r2;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int attempt = 0; attempt < kMaxAttempts; ++attempt) {
    Eigen::Vector3d p;
    if (ellipse_measure < box_measure) {
      // Uniform in the unit ball (disc in the plane) by rejection, then stretched and rotated.
      double x, y, z;
      do {
        x = u(rng), y = u(rng), z = planar_ ? 0.0 : u(rng);
      } while (x * x + y * y + z * z > 1.0);
      p = centre + r1 * x * e1 + r2 * y * e2 + r2 * z * e3;
      if (planar_) p.z() = plane_z_;
      if (inBounds(p)) return p;
    } else {
      p = uniform(rng);
      if ((p - a).norm() + (p - b).norm() <= c_best) return p;
    }
  }
  return uniform(rng);
}

}  // namespace cosim
