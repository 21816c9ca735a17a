#pragma once
// Physical parameters a flight controller needs. sim/ reads them off the loaded MuJoCo model
// (masses, inertias, rotor sites, actuator gears and ranges), so the controller and the physics
// can never disagree about the airframe.
#include <Eigen/Core>
#include <array>

namespace cosim {

struct QuadrotorParams {
  double mass = 1.5;                                  // kg, whole vehicle
  Eigen::Vector3d inertia{0.029, 0.029, 0.055};       // kg m^2, principal, body frame
  std::array<Eigen::Vector2d, 4> rotor_xy{};          // rotor positions in the body x-y plane, m
  std::array<double, 4> spin{{+1, -1, +1, -1}};       // sign of each rotor's reaction torque on z
  double torque_per_thrust = 0.016;                   // k_m / k_f, m
  double min_thrust = 0.0;                            // per rotor, N
  double max_thrust = 8.0;                            // per rotor, N
  double motor_time_constant = 0.03;                  // s, first-order lag
  double gravity = 9.81;                              // m/s^2
  double radius = 0.3;                                // m, bounding radius for clearance

  // A symmetric X layout: rotor i at angle 45 + 90 i degrees, `arm` metres from the centre
  // (front-left, rear-left, rear-right, front-right).
  static std::array<Eigen::Vector2d, 4> xLayout(double arm);
};

}  // namespace cosim
