#include "experiments/bench/bare_replay.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "sim/aerodynamics.h"

namespace cosim::bench {

double bareReplaySeconds(const WorldModel& world, const RunLog& log, const SimSettings& sim,
                         bool follow_logged_state) {
  const mjModel* m = world.model();
  mjData* d = mj_makeData(m);
  const auto& v = world.vehicles()[0];
  const auto& samples = log.vehicles[0].samples;
  const int per_control = static_cast<int>(std::lround(1.0 / (sim.timestep * sim.control_rate)));
  const long steps = log.physics_steps;
  const auto t0 = std::chrono::steady_clock::now();
  Eigen::Vector3d force_body, torque_body;
  for (long k = 0; k < steps; ++k) {
    if (k % per_control == 0) {  // the rotor thrusts the loop applied, held over the period
      const LogSample& x = samples[std::min<std::size_t>(k / per_control, samples.size() - 1)];
      rotorWrench(v.params, x.rotor_thrust, force_body, torque_body);
      if (follow_logged_state) {  // free joint: x y z qw qx qy qz; v (world), w (body)
        mjtNum* q = d->qpos + v.qpos_adr;
        mjtNum* u = d->qvel + v.qvel_adr;
        for (int i = 0; i < 3; ++i) {
          q[i] = x.pos[i];
          u[i] = x.vel[i];
          u[3 + i] = x.omega[i];
        }
        q[3] = x.att.w();
        q[4] = x.att.x();
        q[5] = x.att.y();
        q[6] = x.att.z();
      }
    }
    // The thrust turns with the body: the same O(1) write the loop makes.
    const mjtNum* q = d->qpos + v.qpos_adr + 3;
    setFreeJointWrench(d, v, Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized() * force_body,
                       torque_body);
    mj_step(m, d);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  mj_deleteData(d);
  return seconds;
}

}  // namespace cosim::bench
