#include "sim/aerial_pilot_step.h"

namespace cosim {

VehicleState readVehicleState(const mjModel*, const mjData* d, const VehicleHandles& v) {
  const mjtNum* q = d->qpos + v.qpos_adr;
  const mjtNum* u = d->qvel + v.qvel_adr;
  VehicleState s;
  s.position = {q[0], q[1], q[2]};
  s.attitude = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized();
  s.velocity = {u[0], u[1], u[2]};          // free joint: linear velocity in the world frame
  s.angular_velocity = {u[3], u[4], u[5]};  // free joint: angular velocity in the body frame
  return s;
}

void startHovering(const mjModel* m, mjData* d, const VehicleHandles& v) {
  const double hover = v.params.mass * v.params.gravity / 4.0;
  for (int i = 0; i < 4; ++i) {
    d->ctrl[v.actuators[i]] = hover;
    actuatorActivation(m, d, v.actuators[i]) = hover;
  }
}

AerialStepRules::AerialStepRules(const SimSettings& settings, const World& world,
                                 double hold_after_arrival, double max_saturated_time)
    : goal_tolerance(settings.goal_tolerance),
      hold_after_arrival(hold_after_arrival),
      max_saturated_time(max_saturated_time),
      centre(0.5 * (world.bounds_min + world.bounds_max)),
      far(10.0 * (world.bounds_max - world.bounds_min).norm()) {}

AerialPilotStep::AerialPilotStep(const VehicleHandles& vehicle, VehiclePilot& pilot,
                                 const AerialStepRules& rules)
    : vehicle_(&vehicle), pilot_(&pilot), rules_(rules) {}

VehicleLog AerialPilotStep::begin(std::size_t expected_samples) {
  VehicleLog vl;
  vl.name = vehicle_->name;
  vl.radius = vehicle_->params.radius;
  vl.max_thrust = vehicle_->params.max_thrust;
  vl.goal = pilot_->goal;
  vl.planned_path = pilot_->planned_path;
  vl.samples.reserve(expected_samples);
  pilot_->controller->reset();
  saturated_since_ = -1.0;
  return vl;
}

AerialPilotStep::Outcome AerialPilotStep::step(const mjModel* m, mjData* d, double control_dt,
                                               VehicleLog& vl, bool record) {
  const VehicleHandles& v = *vehicle_;
  const VehicleState s = readVehicleState(m, d, v);
  const FlatReference ref = pilot_->reference->reference(d->time, s);
  const ControlOutput out = pilot_->controller->update(s, ref, control_dt);
  for (int i = 0; i < 4; ++i) d->ctrl[v.actuators[i]] = out.rotor_thrusts[i];

  if (record) {
    LogSample& x = vl.samples.emplace_back();
    x.t = d->time;
    x.ref_pos = ref.position;
    x.ref_vel = ref.velocity;
    x.pos = s.position;
    x.vel = s.velocity;
    x.att = s.attitude;
    x.omega = s.angular_velocity;
    x.rotor_cmd = out.rotor_thrusts;
    for (int i = 0; i < 4; ++i) x.rotor_thrust[i] = actuatorActivation(m, d, v.actuators[i]);
    x.saturated = out.saturated;
  }
  Outcome o;
  if (!out.saturated) {
    saturated_since_ = -1.0;
  } else if (saturated_since_ < 0.0) {
    saturated_since_ = d->time;
  } else if (d->time - saturated_since_ > rules_.max_saturated_time) {
    o.saturated = true;
  }

  // Arrival: on the final set-point and within the goal tolerance.
  if (!vl.reached_goal && pilot_->reference->atFinalSetpoint() &&
      (s.position - pilot_->goal).norm() < rules_.goal_tolerance) {
    vl.reached_goal = true;
    vl.arrival_time = d->time;
  }
  o.done = vl.reached_goal && d->time >= vl.arrival_time + rules_.hold_after_arrival;
  o.diverged = !s.position.allFinite() || (s.position - rules_.centre).norm() > rules_.far;
  return o;
}

}  // namespace cosim
