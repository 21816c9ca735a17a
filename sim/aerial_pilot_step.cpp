#include "sim/aerial_pilot_step.h"

#include "sim/log_growth.h"

namespace cosim {

AerialStepRules::AerialStepRules(const SimSettings& settings, const World& world,
                                 double hold_after_arrival, double max_saturated_time)
    : goal_tolerance(settings.goal_tolerance),
      hold_after_arrival(hold_after_arrival),
      max_saturated_time(max_saturated_time),
      centre(0.5 * (world.bounds_min + world.bounds_max)),
      far(10.0 * (world.bounds_max - world.bounds_min).norm()) {}

AerialPilotStep::AerialPilotStep(const VehicleHandles& vehicle, VehiclePilot& pilot,
                                 const AerialStepRules& rules, const AerialSensing& sensing,
                                 std::size_t vehicle_index)
    : vehicle_(&vehicle),
      pilot_(&pilot),
      rules_(rules),
      airframe_(pilot.believed_airframe ? pilot.believed_airframe : &vehicle.params),
      estimator_(sensing.estimator, sensing.sensors, *airframe_, sensing.seed, vehicle_index) {}

VehicleLog AerialPilotStep::begin(const mjData* d, std::size_t initial_samples,
                                  std::size_t most_samples) {
  VehicleLog vl;
  vl.name = vehicle_->name;
  vl.radius = vehicle_->params.radius;
  vl.max_thrust = vehicle_->params.max_thrust;
  vl.goal = pilot_->goal;
  vl.planned_path = pilot_->planned_path;
  vl.reference_end = pilot_->reference_end;
  // Reserved and written once here; the log then grows with the flight (sim/log_growth.h).
  reserveLogSamples(vl.samples, initial_samples);
  most_samples_ = most_samples;
  pilot_->controller->reset();
  estimator_.begin(d, *vehicle_);
  saturated_since_ = -1.0;
  return vl;
}

AerialPilotStep::Outcome AerialPilotStep::step(const mjData* d, QuadrotorPlant& plant,
                                               double control_dt, VehicleLog& vl, bool record) {
  const VehicleHandles& v = *vehicle_;
  const VehicleState truth = readVehicleState(d, v);
  VehicleState seen = estimator_.estimate(d, v, plant);
  seen.battery_voltage = plant.batteryVoltage();  // the flight software's own measurement
  const FlatReference ref = pilot_->reference->reference(d->time, seen);
  const ControlOutput out = pilot_->controller->update(seen, ref, control_dt);
  if (out.drives_duty) {
    plant.commandDuties(out.motor_duty);
  } else {
    Eigen::Vector4d speeds;
    for (int i = 0; i < 4; ++i) speeds[i] = airframe_->rotorSpeedFor(out.rotor_thrusts[i]);
    plant.rotors().command(speeds);
  }

  if (record) {
    LogSample& x = appendLogSample(vl.samples, most_samples_);
    x.t = d->time;
    x.ref_pos = ref.position;
    x.ref_vel = ref.velocity;
    x.pos = truth.position;
    x.vel = truth.velocity;
    x.att = truth.attitude;
    x.omega = truth.angular_velocity;
    x.est_pos = seen.position;
    x.est_vel = seen.velocity;
    x.est_att = seen.attitude;
    x.rotor_cmd = out.rotor_thrusts;
    x.rotor_speed = plant.rotors().speeds();
    x.rotor_thrust = plant.appliedThrusts();
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

  // Arrival: on the final set-point and within the goal tolerance (of the true position).
  if (!vl.reached_goal && pilot_->reference->atFinalSetpoint() &&
      (truth.position - pilot_->goal).norm() < rules_.goal_tolerance) {
    vl.reached_goal = true;
    vl.arrival_time = d->time;
  }
  o.done = vl.reached_goal && d->time >= vl.arrival_time + rules_.hold_after_arrival;
  o.diverged = !truth.position.allFinite() || (truth.position - rules_.centre).norm() > rules_.far;
  return o;
}

}  // namespace cosim
