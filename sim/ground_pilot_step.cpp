#include "sim/ground_pilot_step.h"

#include <cmath>

#include "sim/log_growth.h"

namespace cosim {

PlanarState readPlanarState(const mjData* d, const VehicleHandles& v) {
  const mjtNum* q = d->qpos + v.qpos_adr;
  const mjtNum* u = d->qvel + v.qvel_adr;
  PlanarState s;
  s.position = {q[0], q[1]};
  s.velocity = {u[0], u[1]};
  if (v.drive.planar_root) {  // slide x, slide y (from the start), hinge yaw
    s.position += v.drive.planar_origin;
    s.yaw = q[2];
    s.yaw_rate = u[2];
  } else {  // free joint: x y z qw qx qy qz; angular velocity in the body frame
    s.yaw = std::atan2(2.0 * (q[3] * q[6] + q[4] * q[5]), 1.0 - 2.0 * (q[5] * q[5] + q[6] * q[6]));
    s.yaw_rate = u[5];
  }
  return s;
}

namespace {

Eigen::Quaterniond attitude(const mjData* d, const VehicleHandles& v) {
  const mjtNum* q = d->qpos + v.qpos_adr;
  if (v.drive.planar_root)
    return Eigen::Quaterniond(Eigen::AngleAxisd(q[2], Eigen::Vector3d::UnitZ()));
  return Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized();
}

// The drive servos' set-points for a body-frame command.
void actuate(PhysicsStepper& physics, std::size_t index, const VehicleHandles& v,
             const PlanarState& s, const GroundCommand& c) {
  if (v.drive.kind == GroundDrive::Kind::Holonomic) {
    const double cy = std::cos(s.yaw), sy = std::sin(s.yaw);
    physics.commandDrive(index, 0, cy * c.forward - sy * c.lateral);
    physics.commandDrive(index, 1, sy * c.forward + cy * c.lateral);
    physics.commandDrive(index, 2, c.yaw_rate);
  } else {
    // Wheel speeds of a differential drive: (v -+ w s / 2) / r.
    const double half = 0.5 * v.drive.wheel_separation * c.yaw_rate;
    physics.commandDrive(index, 0, (c.forward - half) / v.drive.wheel_radius);
    physics.commandDrive(index, 1, (c.forward + half) / v.drive.wheel_radius);
  }
}

}  // namespace

GroundPilotStep::GroundPilotStep(const VehicleHandles& vehicle, std::size_t vehicle_index,
                                 GroundPilot& pilot, double goal_tolerance,
                                 double hold_after_arrival)
    : vehicle_(&vehicle),
      index_(vehicle_index),
      pilot_(&pilot),
      goal_tolerance_(goal_tolerance),
      hold_after_arrival_(hold_after_arrival) {}

VehicleLog GroundPilotStep::begin() {
  VehicleLog vl;
  vl.name = vehicle_->name;
  vl.radius = vehicle_->params.radius;
  vl.goal = pilot_->goal;
  vl.planned_path = pilot_->planned_path;
  pilot_->controller->reset();
  return vl;
}

GroundPilotStep::Outcome GroundPilotStep::step(const mjData* d, const PlanarState& s,
                                               PhysicsStepper& physics, double control_dt,
                                               VehicleLog& vl, bool record) {
  PlanarReference ref = pilot_->path->sample(d->time);
  ref.yaw = pilot_->yaw;
  const GroundCommand cmd = pilot_->controller->update(s, ref, control_dt);
  actuate(physics, index_, *vehicle_, s, cmd);

  // Height: the free base's z; a planar base rides at its fixed height (logged as 0).
  const double z = vehicle_->drive.planar_root ? 0.0 : d->qpos[vehicle_->qpos_adr + 2];
  const Eigen::Vector3d pos(s.position.x(), s.position.y(), z);
  if (!vl.reached_goal && ref.final && (pos - pilot_->goal).head<2>().norm() < goal_tolerance_) {
    vl.reached_goal = true;
    vl.arrival_time = d->time;
  }
  Outcome o;
  o.done = vl.reached_goal && d->time >= vl.arrival_time + hold_after_arrival_;
  o.diverged = !pos.allFinite();
  if (record) recordSample(d, s, ref, pos, cmd, physics, vl);
  return o;
}

void GroundPilotStep::recordSample(const mjData* d, const PlanarState& s,
                                   const PlanarReference& ref, const Eigen::Vector3d& pos,
                                   const GroundCommand& cmd, const PhysicsStepper& physics,
                                   VehicleLog& vl) const {
  LogSample& x = appendLogSample(vl.samples, vl.samples.max_size());
  x.t = d->time;
  x.ref_pos = {ref.position.x(), ref.position.y(), 0.0};
  x.ref_vel = {ref.velocity.x(), ref.velocity.y(), 0.0};
  x.pos = pos;
  x.vel = {s.velocity.x(), s.velocity.y(), 0.0};
  x.att = attitude(d, *vehicle_);
  x.omega = {0.0, 0.0, s.yaw_rate};
  x.est_pos = x.pos;  // a robot's controller reads its exact state
  x.est_vel = x.vel;
  x.est_att = x.att;
  // "Rotor" columns of a ground robot: its drive servos' set-points and forces.
  for (int i = 0; i < vehicle_->drive.servo_count; ++i) {
    x.rotor_cmd[i] = physics.driveCommand(index_, i);
    x.rotor_thrust[i] = physics.driveForce(index_, i);
  }
  x.saturated = cmd.saturated;
}

}  // namespace cosim
