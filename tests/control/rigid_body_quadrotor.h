#pragma once
// A rigid-body quadrotor for closed-loop controller tests: semi-implicit Euler, the rotor-speed
// dynamics of sim/rotor_model.h (each speed follows its command with a first-order lag, time
// constant tau_up while speeding up and tau_down while slowing down, exact over a step; speeds
// clamped), thrust k_f w^2 along body z, torques from the allocation matrix, and optionally the
// rotor drag -m R D R^T v (D = diag(d_x, d_y, d_z) per unit mass, Faessler et al. 2018) and a
// constant external force.
//
// The plant can be a different airframe from the one the controller believes in (a model
// error): it converts the controller's rotor thrusts into speed commands with the believed k_f
// (as flight software does) and reports the measured rotor thrusts the same way, while the
// physics runs on the true mass, inertia and k_f.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "control/flight_controller.h"
#include "control/mixer.h"
#include "control/quadrotor_params.h"

namespace cosim::testing {

// The true airframe behind a believed one. Each factor is belief / truth, as in
// sim/model_error.h: thrust_coefficient 0.95 means the software under-rates its rotors by 5 %.
inline QuadrotorParams trueAirframe(const QuadrotorParams& belief, double mass, double inertia,
                                    double thrust_coefficient) {
  QuadrotorParams truth = belief;
  truth.mass = belief.mass / mass;
  truth.inertia = belief.inertia / inertia;
  truth.thrust_coefficient = belief.thrust_coefficient / thrust_coefficient;
  truth.min_thrust = truth.thrust_coefficient * truth.min_rotor_speed * truth.min_rotor_speed;
  truth.max_thrust = truth.thrust_coefficient * truth.max_rotor_speed * truth.max_rotor_speed;
  return truth;
}

class RigidBodyQuadrotor {
 public:
  // belief: what the controller knows; truth: what flies.
  RigidBodyQuadrotor(const QuadrotorParams& belief, const QuadrotorParams& truth)
      : belief_(belief), truth_(truth), mixer_(truth) {
    rotor_speeds_.setConstant(truth.rotorSpeedFor(truth.mass * truth.gravity / 4.0));
  }
  explicit RigidBodyQuadrotor(const QuadrotorParams& p) : RigidBodyQuadrotor(p, p) {}

  // The kinematic state (position, velocity, attitude, body rates); set it to start anywhere.
  VehicleState state;
  Eigen::Vector3d external_force = Eigen::Vector3d::Zero();  // N, world frame
  Eigen::Vector3d drag_per_mass = Eigen::Vector3d::Zero();   // diag of D, 1/s

  // What the controller measures: the state, the accelerometer's specific force and the rotor
  // thrusts as the believed k_f makes them of the rotor speeds.
  VehicleState measured() const {
    VehicleState m = state;
    m.specific_force = state.attitude.conjugate() *
                       (linearAcceleration() + truth_.gravity * Eigen::Vector3d::UnitZ());
    m.rotor_thrusts = belief_.thrust_coefficient * rotor_speeds_.cwiseAbs2();
    return m;
  }

  void step(const Eigen::Vector4d& thrust_command, double dt) {
    for (int i = 0; i < 4; ++i) {
      const double w_cmd =
          std::clamp(std::sqrt(std::max(thrust_command[i], 0.0) / belief_.thrust_coefficient),
                     truth_.min_rotor_speed, truth_.max_rotor_speed);
      const double tau =
          w_cmd > rotor_speeds_[i] ? truth_.time_constant_up : truth_.time_constant_down;
      rotor_speeds_[i] += (1.0 - std::exp(-dt / tau)) * (w_cmd - rotor_speeds_[i]);
    }
    const Eigen::Vector3d acc = linearAcceleration();
    const Eigen::Vector3d torque = mixer_.wrench(thrusts()).tail<3>();
    const Eigen::Vector3d& w = state.angular_velocity;
    const Eigen::Vector3d w_dot =
        (torque - w.cross(truth_.inertia.cwiseProduct(w))).cwiseQuotient(truth_.inertia);
    state.velocity += acc * dt;
    state.position += state.velocity * dt;
    state.angular_velocity += w_dot * dt;
    const Eigen::Vector3d rot = state.angular_velocity * dt;
    if (rot.norm() > 0.0)
      state.attitude =
          state.attitude * Eigen::Quaterniond(Eigen::AngleAxisd(rot.norm(), rot.normalized()));
    state.attitude.normalize();
  }

  const Eigen::Vector4d& rotorSpeeds() const { return rotor_speeds_; }
  const QuadrotorParams& truth() const { return truth_; }

 private:
  Eigen::Vector4d thrusts() const { return truth_.thrust_coefficient * rotor_speeds_.cwiseAbs2(); }

  // World-frame acceleration at the current state and rotor speeds.
  Eigen::Vector3d linearAcceleration() const {
    const Eigen::Matrix3d R = state.attitude.toRotationMatrix();
    const Eigen::Vector3d drag = -R * drag_per_mass.asDiagonal() * R.transpose() * state.velocity;
    return R.col(2) * thrusts().sum() / truth_.mass - truth_.gravity * Eigen::Vector3d::UnitZ() +
           external_force / truth_.mass + drag;
  }

  QuadrotorParams belief_, truth_;
  Mixer mixer_;
  Eigen::Vector4d rotor_speeds_;
};

}  // namespace cosim::testing
