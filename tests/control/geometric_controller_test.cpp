#include "control/geometric_controller.h"

#include <gtest/gtest.h>

#include <cmath>

#include "control/cascade_controller.h"

using namespace cosim;
using Eigen::Vector3d;

namespace {

QuadrotorParams quad1500g() {
  QuadrotorParams p;
  p.mass = 1.5;
  p.inertia = Vector3d(0.029, 0.029, 0.055);
  p.rotor_xy = QuadrotorParams::xLayout(0.225);
  p.torque_per_thrust = 0.016;
  p.min_thrust = 0.0;
  p.max_thrust = 8.0;
  p.motor_time_constant = 0.03;
  return p;
}

// A Crazyflie 2.x class airframe (about 27 g, thrust-to-weight about 2.2).
QuadrotorParams crazyflieClass() {
  QuadrotorParams p;
  p.mass = 0.027;
  p.inertia = Vector3d(1.4e-5, 1.4e-5, 2.2e-5);
  p.rotor_xy = QuadrotorParams::xLayout(0.046);
  p.torque_per_thrust = 0.006;
  p.max_thrust = 0.15;
  p.motor_time_constant = 0.02;
  p.radius = 0.07;
  return p;
}

// A rigid-body quadrotor for closed-loop tests: semi-implicit Euler at 1 kHz, first-order motor
// lag toward the commanded rotor thrusts (clamped to their range), thrust along body z, torques
// from the same allocation matrix the controller's mixer uses, and an optional constant external
// force (wind).
class RigidBodyQuadrotor {
 public:
  explicit RigidBodyQuadrotor(const QuadrotorParams& p) : p_(p), mixer_(p) {
    rotors_.setConstant(p.mass * p.gravity / 4.0);
  }
  VehicleState state;
  Vector3d external_force = Vector3d::Zero();

  void step(const Eigen::Vector4d& command, double dt) {
    const Eigen::Vector4d u_cmd = command.cwiseMax(p_.min_thrust).cwiseMin(p_.max_thrust);
    rotors_ += (1.0 - std::exp(-dt / p_.motor_time_constant)) * (u_cmd - rotors_);
    const Eigen::Vector4d wrench = mixer_.wrench(rotors_);
    const Eigen::Matrix3d R = state.attitude.toRotationMatrix();
    const Vector3d acc =
        R.col(2) * wrench[0] / p_.mass - p_.gravity * Vector3d::UnitZ() + external_force / p_.mass;
    const Vector3d& w = state.angular_velocity;
    const Vector3d w_dot =
        (wrench.tail<3>() - w.cross(p_.inertia.cwiseProduct(w))).cwiseQuotient(p_.inertia);
    state.velocity += acc * dt;
    state.position += state.velocity * dt;
    state.angular_velocity += w_dot * dt;
    const Vector3d rot = state.angular_velocity * dt;
    if (rot.norm() > 0.0)
      state.attitude =
          state.attitude * Eigen::Quaterniond(Eigen::AngleAxisd(rot.norm(), rot.normalized()));
    state.attitude.normalize();
  }

 private:
  QuadrotorParams p_;
  Mixer mixer_;
  Eigen::Vector4d rotors_;
};

// Flies `controller` for `duration` s against ref(t) (controller at 500 Hz, physics at 1 kHz),
// calling observe() after every physics step; returns the RMS position error over
// [from, duration].
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
    if (k % 2 == 0) out = controller.update(quad.state, ref(t), 2 * dt);
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

FlatReference hoverAt(const Vector3d& p) {
  FlatReference r;
  r.position = p;
  return r;
}

// A horizontal circle of radius r at angular rate w, centred at c, with its derivatives.
FlatReference circle(double t, double r, double w, const Vector3d& c, bool with_jerk = true) {
  const double cs = std::cos(w * t), sn = std::sin(w * t);
  FlatReference ref;
  ref.position = c + r * Vector3d(cs, sn, 0);
  ref.velocity = r * w * Vector3d(-sn, cs, 0);
  ref.acceleration = -r * w * w * Vector3d(cs, sn, 0);
  if (with_jerk) ref.jerk = r * w * w * w * Vector3d(sn, -cs, 0);
  return ref;
}

double tiltDeg(const Eigen::Quaterniond& q) {
  return std::acos(std::clamp(q.toRotationMatrix()(2, 2), -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace

TEST(GeometricController, HoverAtTheReferenceCommandsExactlyTheWeight) {
  const QuadrotorParams p = quad1500g();
  GeometricController controller(p);
  VehicleState s;
  s.position = Vector3d(1, 2, 3);
  const ControlOutput out = controller.update(s, hoverAt(s.position), 0.002);
  EXPECT_NEAR(out.collective_thrust, 1.5 * 9.81, 1e-9);
  EXPECT_LT(out.torque.norm(), 1e-12);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(out.rotor_thrusts[i], 1.5 * 9.81 / 4, 1e-9);
  EXPECT_FALSE(out.saturated);
}

TEST(GeometricController, RecoversFromA90DegreeRoll) {
  const QuadrotorParams p = quad1500g();
  GeometricController controller(p);
  RigidBodyQuadrotor quad(p);
  const Vector3d target(0, 0, 5);
  quad.state.position = target;
  quad.state.attitude = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitX()));
  double lowest = target.z();
  const auto ref = [&](double) { return hoverAt(target); };
  fly(quad, controller, ref, 3.0, 3.0, [&] { lowest = std::min(lowest, quad.state.position.z()); });
  // Back to level (the full attitude error, yaw included) and at the hover point.
  EXPECT_LT(Eigen::AngleAxisd(quad.state.attitude).angle() * 180.0 / M_PI, 5.0);
  EXPECT_LT((quad.state.position - target).norm(), 0.5);
  EXPECT_GT(lowest, target.z() - 1.0);  // it falls while sideways, but less than a metre
}

TEST(GeometricController, TracksACircleToWithinCentimetres) {
  const QuadrotorParams p = quad1500g();
  GeometricController controller(p);
  RigidBodyQuadrotor quad(p);
  const Vector3d c(0, 0, 2);
  // 2 m radius at 1 rad/s: 2 m/s, 2 m/s^2 centripetal. Start on the circle, moving with it.
  const auto ref = [&](double t) { return circle(t, 2.0, 1.0, c); };
  quad.state.position = ref(0).position;
  quad.state.velocity = ref(0).velocity;
  const double rmse = fly(quad, controller, ref, 2.0 + 2 * M_PI, 2.0);  // one lap after 2 s
  EXPECT_LT(rmse, 0.02);
}

TEST(GeometricController, JerkFeedForwardReducesCircleTrackingError) {
  const QuadrotorParams p = quad1500g();
  const Vector3d c(0, 0, 2);
  double rmse[2];
  for (int with_jerk = 0; with_jerk < 2; ++with_jerk) {
    GeometricController controller(p);
    RigidBodyQuadrotor quad(p);
    // A faster circle (3 m/s, 4.5 m/s^2), where the attitude must turn at 1.5 rad/s.
    const auto ref = [&](double t) { return circle(t, 2.0, 1.5, c, with_jerk == 1); };
    quad.state.position = ref(0).position;
    quad.state.velocity = ref(0).velocity;
    rmse[with_jerk] = fly(quad, controller, ref, 6.0, 2.0);
  }
  EXPECT_LT(rmse[1], 0.7 * rmse[0]) << "without jerk " << rmse[0] << " with " << rmse[1];
}

TEST(GeometricController, IntegralRemovesTheOffsetOfAConstantWind) {
  const QuadrotorParams p = quad1500g();
  const Vector3d target(0, 0, 3);
  double error[2];
  for (int with_integral = 0; with_integral < 2; ++with_integral) {
    GeometricGains gains;
    if (!with_integral) gains.k_i = 0.0;
    GeometricController controller(p, gains);
    RigidBodyQuadrotor quad(p);
    quad.state.position = target;
    quad.external_force = Vector3d(1.5, 0, 0);  // 1 m/s^2 on 1.5 kg
    fly(
        quad, controller, [&](double) { return hoverAt(target); }, 12.0, 0.0);
    error[with_integral] = (quad.state.position - target).norm();
  }
  EXPECT_NEAR(error[0], 1.0 / 6.0, 0.01);  // the proportional offset: a / k_x
  EXPECT_LT(error[1], 0.01);
}

TEST(GeometricController, SameGainsFlyACrazyflieClassAirframe) {
  const QuadrotorParams p = crazyflieClass();
  GeometricController controller(p);
  RigidBodyQuadrotor quad(p);
  const Vector3d target(1, 1, 1);
  quad.state.position = Vector3d(0.5, 0.5, 0.8);
  quad.state.attitude = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Vector3d(1, 1, 0).normalized()));
  fly(
      quad, controller, [&](double) { return hoverAt(target); }, 4.0, 0.0);
  EXPECT_LT((quad.state.position - target).norm(), 0.03);
  EXPECT_LT(tiltDeg(quad.state.attitude), 1.0);
}
