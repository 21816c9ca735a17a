#pragma once
// Physical parameters a flight controller needs. sim/ reads them off the loaded MuJoCo model
// (masses, inertias, rotor sites, actuator gears, and the rotor constants of the model file's
// <custom> section), so the controller and the physics start from the same airframe; a
// scenario's `model_error` then scales what the controller believes (sim/model_error.h).
#include <Eigen/Core>
#include <array>
#include <cmath>

namespace cosim {

struct QuadrotorParams {
  double mass = 1.5;                             // kg, whole vehicle
  Eigen::Vector3d inertia{0.029, 0.029, 0.055};  // kg m^2, principal, body frame
  std::array<Eigen::Vector2d, 4> rotor_xy{};     // rotor positions in the body x-y plane, m
  double rotor_z = 0.0;                          // rotor plane height above the centre, m
  std::array<double, 4> spin{{+1, -1, +1, -1}};  // sign of each rotor's reaction torque on z
  double torque_per_thrust = 0.016;              // k_m / k_f, m
  double min_thrust = 0.0;                       // per rotor, N (k_f w_min^2)
  double max_thrust = 8.0;                       // per rotor, N (k_f w_max^2)
  double gravity = 9.81;                         // m/s^2
  double radius = 0.3;                           // m, bounding radius for clearance

  // Rotors (sim/rotor_model.h): each rotor's speed w (rad/s) follows its command with a
  // first-order lag, faster up than down; thrust k_f w^2 along body z.
  double thrust_coefficient = 5.84e-6;  // k_f, N / (rad/s)^2
  double min_rotor_speed = 0.0;         // rad/s
  double max_rotor_speed = 1100.0;      // rad/s
  double time_constant_up = 0.0125;     // s, spin-up
  double time_constant_down = 0.025;    // s, spin-down
  // A pure delay between a rotor's command and the start of its lag (an ESC's processing and
  // PWM period); 0 in models/ unless <numeric name="motor_delay">, or vehicles[i].airframe.
  double motor_delay = 0.0;  // s
  // The motor driven by PWM on a battery (sim/quadrotor_plant.h, a vehicle with
  // vehicles[i].battery): the steady-state rotor speed for the duty cycle d (PWM / 65535) and
  // the battery's terminal voltage V_b is w_ss = c0 + c1 v + c2 v^2 with v = d V_b, the motor's
  // effective voltage (V); c0 rad/s, c1 rad/s/V, c2 rad/s/V^2 (the model file's
  // <numeric name="motor_speed_map">, or vehicles[i].motor_speed_map). Not finite: none given.
  Eigen::Vector3d motor_speed_map = Eigen::Vector3d::Constant(std::nan(""));
  // Rotor aerodynamics (sim/rotor_aerodynamics.h), RotorS / PX4 motor-model form: each rotor
  // adds a drag force -w c_d v_perp and a rolling moment -w c_r v_perp, with v_perp the rotor's
  // air-relative velocity perpendicular to its axis.
  double rotor_drag_coefficient = 0.0;      // c_d, N / (m/s) / (rad/s)
  double rolling_moment_coefficient = 0.0;  // c_r, N m / (m/s) / (rad/s)
  double propeller_radius = 0.12;           // m (ground effect, downwash)
  // Axial inflow at which a rotor at constant speed makes no thrust; thrust falls linearly with
  // inflow from above (a downwash), T = k_f w^2 (1 - v_in / v_0) (PX4 motor model's form).
  double zero_thrust_inflow = 25.0;  // v_0, m/s
  // A team's pairwise separation ellipsoid (planning/team/separation_ellipsoid.h), m.
  double separation_radius = 0.24;
  double separation_height = 0.6;

  // Rotor speed for a given thrust, clamped to [min_rotor_speed, max_rotor_speed].
  double rotorSpeedFor(double thrust) const;
  bool hasMotorSpeedMap() const { return motor_speed_map.allFinite(); }
  // w_ss for a duty cycle and a battery voltage, clamped to [min_rotor_speed, max_rotor_speed].
  double steadyRotorSpeed(double duty, double battery_voltage) const;
  // Hover rotor speed: each rotor carries a quarter of the weight.
  double hoverRotorSpeed() const;
  // The linear drag of Faessler, Franchi and Scaramuzza 2018 (RA-L, eq. 2: a = ... - R D R^T v)
  // per unit mass, in the body frame: rotor drag in hover, d_x = d_y = sum_i w_h c_d / m, none
  // along the rotor axes (d_z = 0). 1/s.
  Eigen::Vector3d linearDragPerMass() const;

  // A symmetric X layout: rotor i at angle 45 + 90 i degrees, `arm` metres from the centre
  // (front-left, rear-left, rear-right, front-right).
  static std::array<Eigen::Vector2d, 4> xLayout(double arm);
};

}  // namespace cosim
