#include "control/mixer.h"

#include <Eigen/LU>
#include <algorithm>

namespace cosim {

Mixer::Mixer(const QuadrotorParams& p) : u_min_(p.min_thrust), u_max_(p.max_thrust) {
  for (int i = 0; i < 4; ++i) {
    A_(0, i) = 1.0;
    A_(1, i) = p.rotor_xy[i].y();   // tau_x = sum y_i u_i  (r x f with f along body z)
    A_(2, i) = -p.rotor_xy[i].x();  // tau_y = -sum x_i u_i
    A_(3, i) = p.spin[i] * p.torque_per_thrust;
  }
  A_inv_ = A_.inverse();
}

Eigen::Vector4d Mixer::allocate(double thrust, const Eigen::Vector3d& torque) const {
  return A_inv_ * Eigen::Vector4d(thrust, torque.x(), torque.y(), torque.z());
}

Eigen::Vector4d Mixer::wrench(const Eigen::Vector4d& u) const { return A_ * u; }

Eigen::Vector4d Mixer::allocateLimited(double thrust, const Eigen::Vector3d& torque,
                                       bool* saturated) const {
  const double span = u_max_ - u_min_;
  const double mid = 0.5 * (u_max_ + u_min_);
  // Each rotor's share of collective thrust is thrust/4 (columns of A^{-1} for f are 1/4).
  Eigen::Vector4d rp = allocate(0.0, {torque.x(), torque.y(), 0.0});  // roll/pitch differential
  const Eigen::Vector4d yaw = allocate(0.0, {0.0, 0.0, torque.z()});
  bool sat = false;

  // 1. Roll/pitch must fit in the range on their own; otherwise scale them down.
  const double rp_spread = rp.maxCoeff() - rp.minCoeff();
  if (rp_spread > span) {
    rp *= span / rp_spread;
    sat = true;
  }
  // 2. Collective: as asked, shifted the least needed to keep every rotor within range.
  double base = thrust / 4.0;
  const double lo = u_min_ - rp.minCoeff(), hi = u_max_ - rp.maxCoeff();
  if (lo > hi) {
    base = mid;
  } else if (base < lo || base > hi) {
    base = std::clamp(base, lo, hi);
    sat = true;
  }
  Eigen::Vector4d u = Eigen::Vector4d::Constant(base) + rp;
  // 3. Yaw: the largest fraction k in [0, 1] of the yaw differential that still fits.
  double k = 1.0;
  for (int i = 0; i < 4; ++i) {
    if (yaw[i] > 1e-12) k = std::min(k, (u_max_ - u[i]) / yaw[i]);
    if (yaw[i] < -1e-12) k = std::min(k, (u_min_ - u[i]) / yaw[i]);
  }
  k = std::max(k, 0.0);
  if (k < 1.0) sat = true;
  u += k * yaw;
  u = u.cwiseMax(u_min_).cwiseMin(u_max_);  // guards rounding only
  if (saturated) *saturated = sat;
  return u;
}

}  // namespace cosim
