#pragma once
// What the closed-loop controller tests share: the two airframes of models/ as a controller
// sees them, flat references with their derivatives, and a flight loop (controller at 500 Hz,
// physics at 1 kHz) that returns the RMS position error.
#include <cmath>

#include "control/flight_controller.h"
#include "tests/control/rigid_body_quadrotor.h"

namespace cosim::testing {

// models/quad_1500g.xml: PX4's Iris (mass, inertia, rotor sites, k_f, w_max, k_m / k_f, rotor
// time constants, rotor drag coefficient), rotors front-left, rear-left, rear-right, front-right.
inline QuadrotorParams quad1500g() {
  QuadrotorParams p;
  p.mass = 1.5;
  p.inertia = Eigen::Vector3d(0.029125, 0.029125, 0.055225);
  p.rotor_xy = {Eigen::Vector2d(0.13, 0.22), Eigen::Vector2d(-0.13, 0.2),
                Eigen::Vector2d(-0.13, -0.2), Eigen::Vector2d(0.13, -0.22)};
  p.torque_per_thrust = 0.06;
  p.thrust_coefficient = 5.84e-6;
  p.min_rotor_speed = 0.0;
  p.max_rotor_speed = 1100.0;
  p.min_thrust = 0.0;
  p.max_thrust = p.thrust_coefficient * p.max_rotor_speed * p.max_rotor_speed;  // 7.07 N
  p.time_constant_up = 0.0125;
  p.time_constant_down = 0.025;
  p.rotor_drag_coefficient = 1.75e-4;
  return p;
}

// models/cf2.xml: a Crazyflie 2.x (27 g, thrust-to-weight about 2.2), with its slower rotors.
inline QuadrotorParams crazyflieClass() {
  QuadrotorParams p;
  p.mass = 0.027;
  p.inertia = Eigen::Vector3d(1.657171e-5, 1.6655602e-5, 2.9261652e-5);
  p.rotor_xy = QuadrotorParams::xLayout(0.046);
  p.torque_per_thrust = 0.005964552;
  p.thrust_coefficient = 2.8816e-8;
  p.min_rotor_speed = 0.0;
  p.max_rotor_speed = 2274.0;
  p.min_thrust = 0.0;
  p.max_thrust = p.thrust_coefficient * p.max_rotor_speed * p.max_rotor_speed;  // 0.149 N
  p.time_constant_up = 0.03;
  p.time_constant_down = 0.06;
  p.rotor_drag_coefficient = 9.1785e-7;
  p.radius = 0.07;
  return p;
}

// The model error of the acceptance scenarios: the controller believes 5 % more mass, 10 % more
// inertia and 5 % less thrust per rotor speed squared than the truth has.
inline QuadrotorParams withModelError(const QuadrotorParams& belief) {
  return trueAirframe(belief, 1.05, 1.10, 0.95);
}

inline FlatReference hoverAt(const Eigen::Vector3d& p) {
  FlatReference r;
  r.position = p;
  return r;
}

// A horizontal circle of radius r at angular rate w, centred at c, with its derivatives (jerk
// and snap only with_jerk).
inline FlatReference circle(double t, double r, double w, const Eigen::Vector3d& c,
                            bool with_jerk = true) {
  const double cs = std::cos(w * t), sn = std::sin(w * t);
  FlatReference ref;
  ref.position = c + r * Eigen::Vector3d(cs, sn, 0);
  ref.velocity = r * w * Eigen::Vector3d(-sn, cs, 0);
  ref.acceleration = -r * w * w * Eigen::Vector3d(cs, sn, 0);
  if (with_jerk) {
    ref.jerk = r * w * w * w * Eigen::Vector3d(sn, -cs, 0);
    ref.snap = r * w * w * w * w * Eigen::Vector3d(cs, sn, 0);
  }
  return ref;
}

// A horizontal figure-eight (lemniscate of Gerono): x = r sin(w t), y = (r / 2) sin(2 w t);
// top speed r w sqrt(2) at the crossing.
inline FlatReference figureEight(double t, double r, double w, const Eigen::Vector3d& c) {
  const double s1 = std::sin(w * t), c1 = std::cos(w * t);
  const double s2 = std::sin(2 * w * t), c2 = std::cos(2 * w * t);
  const double w2 = w * w, w3 = w2 * w, w4 = w3 * w;
  FlatReference ref;
  ref.position = c + Eigen::Vector3d(r * s1, 0.5 * r * s2, 0);
  ref.velocity = Eigen::Vector3d(r * w * c1, r * w * c2, 0);
  ref.acceleration = Eigen::Vector3d(-r * w2 * s1, -2 * r * w2 * s2, 0);
  ref.jerk = Eigen::Vector3d(-r * w3 * c1, -4 * r * w3 * c2, 0);
  ref.snap = Eigen::Vector3d(r * w4 * s1, 8 * r * w4 * s2, 0);
  return ref;
}

// The flat attitude R and specific thrust c of a vehicle on `ref` under rotor drag d_x = d_y = d,
// d_z = 0: (c + d z . v) z = a + g e3 + d v (Faessler et al. 2018), with the heading convention
// of the geometric and INDI controllers (y = z x x_C / |z x x_C|).
inline void flatAttitude(const FlatReference& ref, double d, double g, Eigen::Matrix3d* R,
                         double* c) {
  const Eigen::Vector3d t = ref.acceleration + g * Eigen::Vector3d::UnitZ() + d * ref.velocity;
  const Eigen::Vector3d z = t.normalized();
  const Eigen::Vector3d x_C(std::cos(ref.yaw), std::sin(ref.yaw), 0.0);
  const Eigen::Vector3d y = z.cross(x_C).normalized();
  *R << y.cross(z), y, z;
  *c = t.norm() - d * z.dot(ref.velocity);
}

// Flies `controller` for `duration` s against ref(t) (controller at 500 Hz on what the plant
// measures, physics at 1 kHz), calling observe() after every physics step; returns the RMS
// position error over [from, duration].
template <typename Reference, typename Observer>
double fly(RigidBodyQuadrotor& quad, FlightController& controller, Reference ref, double duration,
           double from, Observer observe) {
  const double dt = 1e-3;
  const int steps = static_cast<int>(std::round(duration / dt));
  ControlOutput out;
  double sum = 0.0;
  int n = 0;
  for (int k = 0; k < steps; ++k) {
    const double t = k * dt;
    if (k % 2 == 0) out = controller.update(quad.measured(), ref(t), 2 * dt);
    quad.step(out.rotor_thrusts, dt);
    observe();
    if (t >= from) {
      sum += (quad.state.position - ref(t + dt).position).squaredNorm();
      ++n;
    }
  }
  return n ? std::sqrt(sum / n) : 0.0;
}

template <typename Reference>
double fly(RigidBodyQuadrotor& quad, FlightController& controller, Reference ref, double duration,
           double from) {
  return fly(quad, controller, ref, duration, from, [] {});
}

// One lap (from 3 s on, after the start transient) of `reference` on the true airframe behind
// quad1500g() with the model error of withModelError and rotor drag (the true airframe's
// linearDragPerMass); the RMS position error.
template <typename Reference>
double flyALapWithDragAndModelError(FlightController& controller, Reference reference, double lap) {
  const QuadrotorParams belief = quad1500g();
  const QuadrotorParams truth = withModelError(belief);
  RigidBodyQuadrotor quad(belief, truth);
  quad.drag_per_mass = truth.linearDragPerMass();
  quad.state.position = reference(0).position;
  quad.state.velocity = reference(0).velocity;
  const double from = 3.0;
  return fly(quad, controller, reference, from + lap, from);
}

inline double tiltDeg(const Eigen::Quaterniond& q) {
  return std::acos(std::clamp(q.toRotationMatrix()(2, 2), -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace cosim::testing
