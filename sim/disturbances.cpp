#include "sim/disturbances.h"

#include <algorithm>
#include <cmath>

namespace cosim {

Disturbances::Disturbances(const DisturbanceSettings& settings, const WorldModel& world,
                           double floor_z, std::uint64_t seed)
    : s_(settings), world_(world), floor_z_(floor_z), rng_(seed ^ 0x9e3779b97f4a7c15ULL) {
  for (const VehicleHandles& v : world.vehicles()) {
    // (A ground robot's entry is unused.) The bounding radius is arm + rotor radius (+ a little): the rotor radius is what is left.
    const double arm = v.params.rotor_xy[0].norm();
    rotor_radius_.push_back(std::max(0.01, v.params.radius - arm));
  }
}

void Disturbances::apply(const mjModel*, mjData* d, double dt) {
  // Gusts: exact discretisation of the Ornstein-Uhlenbeck process over dt.
  if (s_.gust_sigma > 0) {
    const double a = std::exp(-dt / s_.gust_tau);
    const double b = s_.gust_sigma * std::sqrt(1.0 - a * a);
    for (int i = 0; i < 3; ++i) gust_[i] = a * gust_[i] + b * normal_(rng_);
  }
  wind_now_ = s_.wind + gust_;
  for (std::size_t k = 0; k < world_.vehicles().size(); ++k) {
    const VehicleHandles& v = world_.vehicles()[k];
    if (v.ground) continue;  // air drag and wind on a robot's wheels are not what is modelled
    const mjtNum* q = d->qpos + v.qpos_adr;
    const mjtNum* u = d->qvel + v.qvel_adr;
    const Eigen::Vector3d vel(u[0], u[1], u[2]);
    Eigen::Vector3d force = -s_.drag_coefficient * (vel - wind_now_);
    if (s_.ground_effect) {
      const double R = rotor_radius_[k];
      const double z = std::max(q[2] - floor_z_, 0.5 * R);
      const double gain = 1.0 / (1.0 - std::pow(R / (4.0 * z), 2)) - 1.0;
      double thrust = 0.0;
      for (int i = 0; i < 4; ++i) thrust += actuatorActivation(world_.model(), d, v.actuators[i]);
      // Extra thrust along the body z axis (third column of the body rotation).
      const mjtNum* R_body = d->xmat + 9 * v.body;
      force += gain * thrust * Eigen::Vector3d(R_body[2], R_body[5], R_body[8]);
    }
    mjtNum* f = d->xfrc_applied + 6 * v.body;
    f[0] = force.x();
    f[1] = force.y();
    f[2] = force.z();
  }
}

}  // namespace cosim
