#include "sim/aerodynamics.h"

#include <algorithm>

#include "sim/downwash.h"
#include "sim/ground_effect.h"
#include "sim/rotor_aerodynamics.h"

namespace cosim {

namespace {

Eigen::Matrix3d bodyRotation(const mjData* d, const VehicleHandles& v) {
  const mjtNum* q = d->qpos + v.qpos_adr + 3;
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
}

Eigen::Vector3d rotorHub(const mjData* d, const VehicleHandles& v, const Eigen::Matrix3d& R,
                         int i) {
  const mjtNum* q = d->qpos + v.qpos_adr;
  const QuadrotorParams& p = v.params;
  return Eigen::Vector3d(q[0], q[1], q[2]) +
         R * Eigen::Vector3d(p.rotor_xy[i].x(), p.rotor_xy[i].y(), p.rotor_z);
}

}  // namespace

Aerodynamics::Aerodynamics(const DisturbanceSettings& settings, const WorldModel& world,
                           std::uint64_t seed)
    : s_(settings),
      world_(world),
      wind_(settings, seed),
      factors_(4 * world.vehicles().size(), 1.0) {}

void Aerodynamics::apply(const mjModel* m, mjData* d, const std::vector<const RotorModel*>& rotors,
                         double dt) {
  const auto& vehicles = world_.vehicles();
  if (s_.hasWind()) wind_.advance(dt);

  // Thrust factors: downwash needs every rotor's hub and thrust first.
  std::fill(factors_.begin(), factors_.end(), 1.0);
  if (s_.downwash) {
    std::vector<WakeSource> hubs;
    std::vector<std::size_t> owner;  // index into factors_
    for (std::size_t v = 0; v < vehicles.size(); ++v) {
      if (!rotors[v]) continue;
      const Eigen::Matrix3d R = bodyRotation(d, vehicles[v]);
      const Eigen::Vector4d thrust = rotors[v]->thrusts();
      for (int i = 0; i < 4; ++i) {
        hubs.push_back({rotorHub(d, vehicles[v], R, i), static_cast<int>(v),
                        vehicles[v].params.propeller_radius, thrust[i]});
        owner.push_back(4 * v + i);
      }
    }
    const std::vector<double> inflow = downwashInflow(hubs);
    for (std::size_t k = 0; k < hubs.size(); ++k) {
      const double v0 = vehicles[owner[k] / 4].params.zero_thrust_inflow;
      factors_[owner[k]] = std::max(0.0, 1.0 - inflow[k] / v0);
    }
  }

  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    if (!rotors[v]) continue;
    const VehicleHandles& h = vehicles[v];
    const QuadrotorParams& p = h.params;
    const Eigen::Matrix3d R = bodyRotation(d, h);
    const Eigen::Vector4d thrust = rotors[v]->thrusts();
    for (int i = 0; i < 4; ++i) {
      double& f = factors_[4 * v + i];
      if (s_.ground_effect) {
        // Beyond 5 radii the gain is below 0.3 %: no need to look further.
        const double z = surfaceDistanceBelow(m, d, rotorHub(d, h, R, i), R.col(2), h.body,
                                              5.0 * p.propeller_radius);
        f *= groundEffectFactor(p.propeller_radius, z);
      }
      d->ctrl[h.actuators[i]] = f * thrust[i];
    }
    if (!s_.hasDrag()) continue;
    const mjtNum* u = d->qvel + h.qvel_adr;
    AirframeMotion motion;
    motion.R = R;
    motion.velocity = {u[0], u[1], u[2]};
    motion.angular_velocity = {u[3], u[4], u[5]};
    motion.wind = wind_.velocity();
    Wrench w;
    if (s_.rotor_drag) w = rotorDragWrench(p, motion, rotors[v]->speeds());
    w.force += -s_.drag_coefficient * (motion.velocity - motion.wind);
    mjtNum* x = d->xfrc_applied + 6 * h.body;
    for (int k = 0; k < 3; ++k) {
      x[k] = w.force[k];
      x[3 + k] = w.torque[k];
    }
  }
}

}  // namespace cosim
