#pragma once
// Random states for the sampling planners: uniform in the bounds (in the plane z = const for
// ground robots), or uniform in the informed set of Informed RRT* (Gammell, Srinivasa & Barfoot
// 2014, "Informed RRT*: optimal sampling-based path planning focused via direct sampling of an
// admissible ellipsoidal heuristic"): the prolate hyperspheroid of points x with
// |x - start| + |x - goal| <= c_best, intersected with the bounds.
#include <Eigen/Core>
#include <random>

namespace cosim {

class StateSampler {
 public:
  // planar: every sample has z = plane_z (bounds' z range ignored).
  StateSampler(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, bool planar, double plane_z);

  Eigen::Vector3d uniform(std::mt19937_64& rng) const;
  // A sample uniform over {x in bounds : |x - a| + |x - b| <= c_best} (c_best > |b - a|).
  Eigen::Vector3d informed(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double c_best,
                           std::mt19937_64& rng) const;

 private:
  bool inBounds(const Eigen::Vector3d& p) const;
  Eigen::Vector3d lo_, hi_;
  bool planar_;
  double plane_z_;
};

}  // namespace cosim
