#pragma once
// Everything the air does to the quadrotors at one physics step, from the scenario's
// `disturbances:` (ground robots feel none of it):
// - each rotor's thrust k_f w^2 (sim/rotor_model.h) times its ground-effect factor
//   (sim/ground_effect.h) and its downwash factor 1 - u / v_0 (sim/downwash.h), handed to MuJoCo
//   as the rotor actuator's control, so it acts at the rotor with its reaction torque;
// - rotor drag and rolling moments (sim/rotor_aerodynamics.h) and the lumped drag
//   -k (v - wind), against the wind of sim/wind.h, as a wrench on the body (d->xfrc_applied).
#include <mujoco/mujoco.h>

#include <cstdint>
#include <vector>

#include "sim/disturbance_settings.h"
#include "sim/rotor_model.h"
#include "sim/wind.h"
#include "sim/world_model.h"

namespace cosim {

class Aerodynamics {
 public:
  Aerodynamics(const DisturbanceSettings& settings, const WorldModel& world, std::uint64_t seed);

  // Call before each mj_step, after the rotors have advanced: `rotors[v]` is vehicle v's rotor
  // state (nullptr for a ground robot). Sets d->ctrl of every rotor actuator and, when any drag
  // is on, d->xfrc_applied of every quadrotor body.
  void apply(const mjModel* m, mjData* d, const std::vector<const RotorModel*>& rotors, double dt);

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
