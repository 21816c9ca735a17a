#include "sim/physics_stepper.h"

#include <algorithm>
#include <cmath>

#include "sim/simulation_health.h"

namespace cosim {

PhysicsStepper::PhysicsStepper(const WorldModel& world, const Scenario& scenario,
                               const SimSettings& settings)
    : m_(world.model()),
      steps_per_control_(std::max(
          1, static_cast<int>(std::lround(1.0 / (settings.timestep * settings.control_rate))))),
      control_dt_(steps_per_control_ * m_->opt.timestep),
      max_steps_(static_cast<long>(std::ceil(settings.max_time / m_->opt.timestep))),
      contacts_(m_, world, scenario),
      disturbances_(scenario.disturbances, world, scenario.world.bounds_min.z(), scenario.sim.seed),
      disturbed_(scenario.disturbances.any()) {}

const char* PhysicsStepper::step(mjData* d, RunLog& log) {
  if (disturbed_) disturbances_.apply(m_, d, m_->opt.timestep);
  mj_step(m_, d);
  ++steps_;
  contacts_.update(d, log);
  return physicsFault(m_, d);
}

void PhysicsStepper::finish(const mjData* d, RunLog& log) const {
  log.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
  log.sim_time = d->time;
  log.physics_steps = steps_;
  for (int i = 0; i < mjNWARNING; ++i) log.mujoco_warnings += d->warning[i].number;
}

}  // namespace cosim
