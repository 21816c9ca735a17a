#include "sim/ground_effect.h"

#include <algorithm>

namespace cosim {

double groundEffectFactor(double R, double z) {
  if (z < 0.0) return 1.0;
  const double r = R / (4.0 * std::max(z, 0.5 * R));
  return 1.0 / (1.0 - r * r);
}

double surfaceDistanceBelow(const mjModel* m, const mjData* d, const Eigen::Vector3d& rotor,
                            const Eigen::Vector3d& axis, int vehicle_body, double range) {
  const mjtNum pnt[3] = {rotor.x(), rotor.y(), rotor.z()};
  const mjtNum vec[3] = {-axis.x(), -axis.y(), -axis.z()};
  int geom = -1;
  // flg_static 1: static geoms (the floor, obstacles) count; vehicle_body is excluded.
  const mjtNum dist = mj_ray(m, d, pnt, vec, nullptr, 1, vehicle_body, &geom);
  return (geom < 0 || dist < 0.0 || dist > range) ? -1.0 : dist;
}

}  // namespace cosim
