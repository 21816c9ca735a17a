#include "sim/physics_stepper.h"

#include <algorithm>
#include <cmath>

#include "sim/simulation_health.h"

namespace cosim {

PhysicsStepper::PhysicsStepper(const WorldModel& world, const Scenario& scenario,
                               const SimSettings& settings)
    : m_(world.model()),
      world_(world),
      steps_per_control_(std::max(
          1, static_cast<int>(std::lround(1.0 / (settings.timestep * settings.control_rate))))),
      control_dt_(steps_per_control_ * m_->opt.timestep),
      max_steps_(static_cast<long>(std::ceil(settings.max_time / m_->opt.timestep))),
      contacts_(m_, world, scenario),
      aerodynamics_(scenario.disturbances, world, scenario.sim.seed),
      sensing_(!scenario.sensors.ideal()),
      ground_effect_(scenario.disturbances.ground_effect) {
  const auto& vehicles = world.vehicles();
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    plants_.push_back(
        vehicles[v].kind == VehicleKind::GroundRobot
            ? nullptr
            : std::make_unique<QuadrotorPlant>(
                  vehicles[v], scenario.sensors, scenario.sim.seed, v,
                  scenario.vehicles[v].battery ? &*scenario.vehicles[v].battery : nullptr));
    plant_pointers_.push_back(plants_.back().get());
  }
  drive_command_.assign(vehicles.size(), {0.0, 0.0, 0.0});
  drive_force_.assign(vehicles.size(), {0.0, 0.0, 0.0});
}

void PhysicsStepper::commandDrive(std::size_t v, int servo, double speed) {
  const GroundDrive::Servo& s = world_.vehicles()[v].drive.servos[servo];
  drive_command_[v][servo] = std::clamp(speed, -s.max_speed, s.max_speed);
}

void PhysicsStepper::startHovering(mjData* d) {
  const auto& vehicles = world_.vehicles();
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    if (!plants_[v]) continue;
    const QuadrotorParams& p = vehicles[v].params;
    plants_[v]->rotors().reset(Eigen::Vector4d::Constant(p.hoverRotorSpeed()));
  }
  // The wrench of hovering rotors, so that the first mj_forward sees it too.
  aerodynamics_.apply(m_, d, plant_pointers_, 0.0);
}

std::optional<RunEnd> PhysicsStepper::step(mjData* d, RunLog& log) {
  applyForces(d);
  mj_step(m_, d);
  return afterStep(d, log);
}

void PhysicsStepper::applyForces(mjData* d) {
  const double dt = m_->opt.timestep;
  for (auto& p : plants_)
    if (p) p->advanceRotors(dt);
  aerodynamics_.apply(m_, d, plant_pointers_, dt);
  // The robots' velocity servos, with the joint speeds at the start of the step (as a MuJoCo
  // velocity actuator computes its force).
  const auto& vehicles = world_.vehicles();
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    const GroundDrive& drive = vehicles[v].drive;
    for (int i = 0; i < drive.servo_count; ++i) {
      const GroundDrive::Servo& s = drive.servos[i];
      const double f =
          std::clamp(s.kv * (drive_command_[v][i] - d->qvel[s.dof]), -s.max_force, s.max_force);
      d->qfrc_applied[s.dof] = drive_force_[v][i] = f;
    }
  }
}

std::optional<RunEnd> PhysicsStepper::afterStep(mjData* d, RunLog& log) {
  ++steps_;
  contacts_.update(d, log);
  if (sensing_)
    for (auto& p : plants_)
      if (p) p->sense(d);
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
