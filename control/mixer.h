#pragma once
// Control allocation for a quadrotor ("determination of angular rates" in seed 003, Fig. 2):
// maps the collective thrust f and body torques tau to the four rotor thrusts, and back.
//   [f, tau_x, tau_y, tau_z]^T = A u,  A = [1 ...; y_i ...; -x_i ...; s_i k ...]
// where rotor i sits at (x_i, y_i) and its reaction torque about z is s_i k u_i.
#include <Eigen/Core>

#include "control/quadrotor_params.h"

namespace cosim {

class Mixer {
 public:
  explicit Mixer(const QuadrotorParams& params);

  // Exact inverse, no limits: u = A^{-1} [f; tau].
  Eigen::Vector4d allocate(double thrust, const Eigen::Vector3d& torque) const;
  // Forward map: [f; tau] = A u.
  Eigen::Vector4d wrench(const Eigen::Vector4d& rotor_thrusts) const;

  // Saturation-aware allocation within [min_thrust, max_thrust] per rotor. Priorities: roll and
  // pitch torque first (scaled down only if they alone do not fit), then the collective thrust
  // (shifted as little as possible), then yaw torque (scaled to what remains). Sets `saturated`
  // if the result differs from the exact allocation.
  Eigen::Vector4d allocateLimited(double thrust, const Eigen::Vector3d& torque,
                                  bool* saturated = nullptr) const;

  const Eigen::Matrix4d& allocationMatrix() const { return A_; }

 private:
  Eigen::Matrix4d A_, A_inv_;
  double u_min_, u_max_;
};

}  // namespace cosim
