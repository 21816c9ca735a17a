#pragma once
// The aerodynamic force and moment each spinning rotor adds in translational flight, in the form
// of the RotorS and PX4 motor models (PX4-SITL_gazebo-classic, src/gazebo_motor_model.cpp, after
// P. Martin and E. Salaun, "The true role of accelerometer feedback in quadrotor control", ICRA
// 2010): with v_perp the rotor hub's air-relative velocity perpendicular to the rotor axis,
//   rotor drag       F_i = -w_i c_d v_perp,i              (blade flapping and induced drag)
//   rolling moment   M_i = -w_i s_i c_r v_perp,i           (s_i = +1 counter-clockwise rotor)
// both scaled by the rotor speed w_i, not by a constant: a rotor that turns faster drags more,
// which is why one drag coefficient in N/(m/s) cannot suit a 27 g and a 1.5 kg airframe. Their
// sum over the rotors is the linear drag -R D R^T v of Faessler et al. 2018 in hover.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "control/quadrotor_params.h"

namespace cosim {

// The vehicle's motion the aerodynamics depends on (world frame unless stated).
struct AirframeMotion {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();             // body to world
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // of the centre of mass
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // body frame
  Eigen::Vector3d wind = Eigen::Vector3d::Zero();
};

struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // at the centre of mass
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // about the centre of mass
};

// The sum over the four rotors of F_i (with its moment about the centre, r_i x F_i) and M_i, in
// the world frame.
Wrench rotorDragWrench(const QuadrotorParams& airframe, const AirframeMotion& motion,
                       const Eigen::Vector4d& rotor_speeds);
// The same sums in the body frame (force and torque both), as the physics step applies them.
Wrench rotorDragWrenchBody(const QuadrotorParams& airframe, const AirframeMotion& motion,
                           const Eigen::Vector4d& rotor_speeds);

}  // namespace cosim
