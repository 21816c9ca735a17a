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

void rotorWrench(const QuadrotorParams& p, const Eigen::Vector4d& thrusts,
                 Eigen::Vector3d& force_body, Eigen::Vector3d& torque_body) {
  force_body = Eigen::Vector3d(0.0, 0.0, thrusts.sum());
  torque_body.setZero();
  for (int i = 0; i < 4; ++i) {
    // r_i x (0, 0, T_i) = (y_i T_i, -x_i T_i, 0), plus the reaction s_i k T_i about z.
    torque_body.x() += p.rotor_xy[i].y() * thrusts[i];
    torque_body.y() -= p.rotor_xy[i].x() * thrusts[i];
    torque_body.z() += p.spin[i] * p.torque_per_thrust * thrusts[i];
  }
}

void setFreeJointWrench(mjData* d, const VehicleHandles& h, const Eigen::Vector3d& force_world,
                        const Eigen::Vector3d& torque_body) {
  mjtNum* q = d->qfrc_applied + h.qvel_adr;
  for (int k = 0; k < 3; ++k) {
    q[k] = force_world[k];
    q[3 + k] = torque_body[k];
  }
}

Aerodynamics::Aerodynamics(const DisturbanceSettings& settings, const WorldModel& world,
                           std::uint64_t seed)
    : s_(settings),
      world_(world),
      wind_(settings, seed),
      factors_(4 * world.vehicles().size(), 1.0) {}

void Aerodynamics::apply(const mjModel* m, mjData* d, const std::vector<QuadrotorPlant*>& plants,
                         double dt) {
  const auto& vehicles = world_.vehicles();
  if (s_.hasWind()) wind_.advance(dt);

  // Thrust factors: downwash needs every rotor's hub and thrust first.
  std::fill(factors_.begin(), factors_.end(), 1.0);
  if (s_.downwash) {
    std::vector<WakeSource> hubs;
    std::vector<std::size_t> owner;  // index into factors_
    for (std::size_t v = 0; v < vehicles.size(); ++v) {
      if (!plants[v]) continue;
      const Eigen::Matrix3d R = bodyRotation(d, vehicles[v]);
      const Eigen::Vector4d thrust = plants[v]->rotors().thrusts();
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
    if (!plants[v]) continue;
    const VehicleHandles& h = vehicles[v];
    const QuadrotorParams& p = h.params;
    const RotorModel& rotors = plants[v]->rotors();
    const Eigen::Matrix3d R = bodyRotation(d, h);
    Eigen::Vector4d thrust = rotors.thrusts();
    for (int i = 0; i < 4; ++i) {
      double& f = factors_[4 * v + i];
      if (s_.ground_effect) {
        // Beyond 5 radii the gain is below 0.3 %: no need to look further.
        const double z = surfaceDistanceBelow(m, d, rotorHub(d, h, R, i), R.col(2), h.body,
                                              5.0 * p.propeller_radius);
        f *= groundEffectFactor(p.propeller_radius, z);
      }
      thrust[i] *= f;
    }
    plants[v]->setAppliedThrusts(thrust);
    Eigen::Vector3d force_body, torque_body;
    rotorWrench(p, thrust, force_body, torque_body);
    Wrench air;                                             // rotor drag, body frame
    Eigen::Vector3d linear_drag = Eigen::Vector3d::Zero();  // world frame
    if (s_.hasDrag()) {
      const mjtNum* u = d->qvel + h.qvel_adr;
      AirframeMotion motion;
      motion.R = R;
      motion.velocity = {u[0], u[1], u[2]};
      motion.angular_velocity = {u[3], u[4], u[5]};
      motion.wind = wind_.velocity();
      if (s_.rotor_drag) air = rotorDragWrenchBody(p, motion, rotors.speeds());
      linear_drag = -s_.drag_coefficient * (motion.velocity - motion.wind);
    }
    setFreeJointWrench(d, h, R * (force_body + air.force) + linear_drag, torque_body + air.torque);
  }
}

}  // namespace cosim
