#pragma once
// Everything the rotors and the air do to the quadrotors at one physics step (ground robots feel
// none of it), written as one wrench on each quadrotor's free joint (d->qfrc_applied: the force
// in the world frame, the moment in the body frame, both about the centre of mass):
// - each rotor's thrust k_f w^2 (sim/rotor_model.h) times its ground-effect factor
//   (sim/ground_effect.h) and its downwash factor 1 - u / v_0 (sim/downwash.h), along body z at
//   the rotor's site, with its reaction torque s_i (k_m / k_f) T_i about body z;
// - with `disturbances:`, rotor drag and rolling moments (sim/rotor_aerodynamics.h) and the
//   lumped drag -k (v - wind), against the wind of sim/wind.h.
// Writing the generalized force directly costs O(1) per vehicle; MuJoCo's site actuators and
// xfrc_applied each cost an nv-long Jacobian, which with many vehicles was most of a step.
#include <mujoco/mujoco.h>

#include <cstdint>
#include <vector>

#include "sim/disturbance_settings.h"
#include "sim/quadrotor_plant.h"
#include "sim/wind.h"
#include "sim/world_model.h"

namespace cosim {

// The rotors' own wrench in the body frame for the thrusts `thrusts` (N): the sum of the thrusts
// along body z, and the moment of each about the centre of mass plus its reaction torque.
void rotorWrench(const QuadrotorParams& airframe, const Eigen::Vector4d& thrusts,
                 Eigen::Vector3d& force_body, Eigen::Vector3d& torque_body);

// Sets vehicle h's free-joint generalized force in d->qfrc_applied: `force_world` at the centre
// of mass and `torque_body` about it (the body-frame moment the free joint's angular dofs take).
void setFreeJointWrench(mjData* d, const VehicleHandles& h, const Eigen::Vector3d& force_world,
                        const Eigen::Vector3d& torque_body);

class Aerodynamics {
 public:
  Aerodynamics(const DisturbanceSettings& settings, const WorldModel& world, std::uint64_t seed);

  // Call before each mj_step, after the rotors have advanced: `plants[v]` is vehicle v's rotors
  // and sensors (nullptr for a ground robot). Sets the quadrotors' dofs of d->qfrc_applied and
  // each plant's applied rotor thrusts.
  void apply(const mjModel* m, mjData* d, const std::vector<QuadrotorPlant*>& plants, double dt);

  const Eigen::Vector3d& wind() const { return wind_.velocity(); }
  // Vehicle v's rotor i thrust factor of the last step (ground effect x downwash), for tests.
  double thrustFactor(std::size_t v, int i) const { return factors_[4 * v + i]; }

 private:
  DisturbanceSettings s_;
  const WorldModel& world_;
  Wind wind_;
  std::vector<double> factors_;  // 4 per vehicle
};

}  // namespace cosim
