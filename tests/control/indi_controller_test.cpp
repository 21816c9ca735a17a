#include "control/indi_controller.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "control/geometric_controller.h"
#include "tests/control/closed_loop_flight.h"

using namespace cosim;
using namespace cosim::testing;
using Eigen::Vector3d;

namespace {

// What a vehicle hovering still measures: its weight on the accelerometer, and rotor thrusts.
VehicleState hovering(const Vector3d& p, const QuadrotorParams& params, double thrust_each) {
  VehicleState s;
  s.position = p;
  s.specific_force = Vector3d(0, 0, params.gravity);
  s.rotor_thrusts.setConstant(thrust_each);
  return s;
}

// A climbing, yawing circle: every term of the feed-forward is exercised.
FlatReference yawingHelix(double t) {
  FlatReference ref = circle(t, 3.0, 1.3, Vector3d(0, 0, 2));
  ref.position.z() += 0.5 * t * t;
  ref.velocity.z() += t;
  ref.acceleration.z() += 1.0;
  ref.yaw = 0.4 + 0.3 * t + 0.2 * t * t;
  ref.yaw_rate = 0.3 + 0.4 * t;
  ref.yaw_acceleration = 0.4;
  return ref;
}

}  // namespace

TEST(IndiController, HoverKeepsTheMeasuredThrustNotTheModelledWeight) {
  // The rotors measure 3 % more thrust than the believed weight needs while the accelerometer
  // says the vehicle is not accelerating: INDI keeps what the rotors make, where a model-based
  // controller would command m g.
  const QuadrotorParams p = quad1500g();
  IndiController controller(p);
  const double each = 1.03 * p.mass * p.gravity / 4;
  const VehicleState s = hovering(Vector3d(1, 2, 3), p, each);
  const ControlOutput out = controller.update(s, hoverAt(s.position), 0.002);
  EXPECT_NEAR(out.collective_thrust, 4 * each, 1e-9);
  EXPECT_LT(out.torque.norm(), 1e-12);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(out.rotor_thrusts[i], each, 1e-9);
  EXPECT_FALSE(out.saturated);
}

TEST(IndiController, AMeasuredSinkRaisesTheThrustByTheMassTimesIt) {
  // Falling at 1 m/s^2 with no reference acceleration (a gust pushing down): the increment adds
  // m * 1 m/s^2 to the measured thrust, once the filter has settled on the measurement.
  const QuadrotorParams p = quad1500g();
  IndiController controller(p);
  const double each = p.mass * p.gravity / 4;
  VehicleState s = hovering(Vector3d::Zero(), p, each);
  s.specific_force.z() = p.gravity - 1.0;
  ControlOutput out;
  for (int k = 0; k < 500; ++k) out = controller.update(s, hoverAt(Vector3d::Zero()), 0.002);
  EXPECT_NEAR(out.collective_thrust, p.mass * p.gravity + p.mass * 1.0, 1e-6);
}

TEST(IndiController, FeedForwardMatchesTheRatesOfTheFlatAttitude) {
  // Body rates and angular accelerations against central differences of the flat attitude of a
  // climbing, yawing circle, with and without rotor drag.
  const double g = 9.81, h = 1e-4;
  for (double d : {0.0, 0.37}) {
    const Vector3d D(d, d, 0.0);
    for (double t : {0.3, 1.1, 2.0}) {
      Eigen::Matrix3d R[3];
      double c[3];
      for (int k = 0; k < 3; ++k) flatAttitude(yawingHelix(t + (k - 1) * h), d, g, &R[k], &c[k]);
      const auto rates = [&](int k) {
        const IndiController::FeedForward ff =
            IndiController::feedForward(R[k], c[k], yawingHelix(t + (k - 1) * h), D);
        return ff.omega;
      };
      // omega^ = R^T dR/dt.
      const Eigen::Matrix3d W = R[1].transpose() * (R[2] - R[0]) / (2 * h);
      const Vector3d omega_fd(W(2, 1), W(0, 2), W(1, 0));
      const IndiController::FeedForward ff =
          IndiController::feedForward(R[1], c[1], yawingHelix(t), D);
      EXPECT_LT((ff.omega - omega_fd).norm(), 1e-5 * (1 + omega_fd.norm()))
          << "d " << d << " t " << t << ": " << ff.omega.transpose() << " vs "
          << omega_fd.transpose();
      const Vector3d omega_dot_fd = (rates(2) - rates(0)) / (2 * h);
      EXPECT_LT((ff.omega_dot - omega_dot_fd).norm(), 1e-4 * (1 + omega_dot_fd.norm()))
          << "d " << d << " t " << t << ": " << ff.omega_dot.transpose() << " vs "
          << omega_dot_fd.transpose();
      EXPECT_GT(ff.omega.norm(), 0.5);  // the test exercises non-trivial rates
    }
  }
}

TEST(IndiController, RejectsAConstantSideForceTheGeometricControllerCannot) {
  // 0.3 g pushing sideways on the hovering Iris: INDI measures it and holds the point; the
  // geometric controller without its integral is left at the offset a / k_x.
  const QuadrotorParams p = quad1500g();
  const Vector3d target(0, 0, 3);
  const Vector3d push(0.3 * p.mass * p.gravity, 0, 0);
  double error[2];
  for (int which = 0; which < 2; ++which) {
    GeometricGains no_integral;
    no_integral.k_i = 0.0;
    IndiController indi(p);
    GeometricController geometric(p, no_integral);
    FlightController& controller = which == 0 ? static_cast<FlightController&>(indi)
                                              : static_cast<FlightController&>(geometric);
    RigidBodyQuadrotor quad(p);
    quad.state.position = target;
    quad.external_force = push;
    fly(
        quad, controller, [&](double) { return hoverAt(target); }, 8.0, 0.0);
    error[which] = (quad.state.position - target).norm();
  }
  EXPECT_LT(error[0], 0.01);
  EXPECT_NEAR(error[1], 0.3 * 9.81 / 6.0, 0.01);
}

TEST(IndiController, SameGainsFlyACrazyflieClassAirframe) {
  const QuadrotorParams p = crazyflieClass();
  IndiController controller(p);
  RigidBodyQuadrotor quad(p, withModelError(p));
  const Vector3d target(1, 1, 1);
  quad.state.position = Vector3d(0.5, 0.5, 0.8);
  quad.state.attitude = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Vector3d(1, 1, 0).normalized()));
  fly(
      quad, controller, [&](double) { return hoverAt(target); }, 4.0, 0.0);
  EXPECT_LT((quad.state.position - target).norm(), 0.01);
  EXPECT_LT(tiltDeg(quad.state.attitude), 1.0);
}

TEST(IndiController, RecoversFromA90DegreeRoll) {
  const QuadrotorParams p = quad1500g();
  IndiController controller(p);
  RigidBodyQuadrotor quad(p);
  const Vector3d target(0, 0, 5);
  quad.state.position = target;
  quad.state.attitude = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitX()));
  double lowest = target.z();
  fly(
      quad, controller, [&](double) { return hoverAt(target); }, 3.0, 3.0,
      [&] { lowest = std::min(lowest, quad.state.position.z()); });
  EXPECT_LT(Eigen::AngleAxisd(quad.state.attitude).angle() * 180.0 / M_PI, 5.0);
  EXPECT_LT((quad.state.position - target).norm(), 0.5);
  EXPECT_GT(lowest, target.z() - 1.0);
}

// The acceptance target of the project: on fast horizontal manoeuvres with rotor drag and the
// model error, INDI with drag compensation has at most half the RMS error of the geometric
// controller. (On this ideal plant, no sensor noise or delay, it does far better: about 0.02.)
TEST(IndiController, HalvesTheGeometricErrorOnAFastCircleWithDragAndModelError) {
  const Vector3d c(0, 0, 3);
  const double r = 8.0;
  for (double speed : {4.0, 6.0, 8.0}) {
    const double w = speed / r;
    const auto ref = [&](double t) { return circle(t, r, w, c); };
    const QuadrotorParams belief = quad1500g();
    GeometricController geometric(belief);
    IndiController indi(belief), indi_drag(belief, {}, true);
    const double e_geometric = flyALapWithDragAndModelError(geometric, ref, 2 * M_PI / w);
    const double e_indi = flyALapWithDragAndModelError(indi, ref, 2 * M_PI / w);
    const double e_indi_drag = flyALapWithDragAndModelError(indi_drag, ref, 2 * M_PI / w);
    std::printf(
        "circle %.0f m/s: rmse geometric %.4f, indi %.4f, indi+drag %.4f m; "
        "indi+drag / geometric %.3f\n",
        speed, e_geometric, e_indi, e_indi_drag, e_indi_drag / e_geometric);
    EXPECT_LT(e_indi_drag, 0.5 * e_geometric) << speed << " m/s";
    // The drag terms of the feed-forward (attitude rates) matter too: half the error at 8 m/s.
    EXPECT_LT(e_indi_drag, e_indi) << speed << " m/s";
    EXPECT_LT(e_indi_drag, 0.01) << speed << " m/s";
  }
}

TEST(IndiController, HalvesTheGeometricErrorOnAFastFigureEightWithDragAndModelError) {
  const Vector3d c(0, 0, 3);
  const double r = 8.0;
  for (double top_speed : {4.0, 6.0, 8.0}) {
    const double w = top_speed / (r * std::sqrt(2.0));
    const auto ref = [&](double t) { return figureEight(t, r, w, c); };
    const QuadrotorParams belief = quad1500g();
    GeometricController geometric(belief);
    IndiController indi_drag(belief, {}, true);
    const double e_geometric = flyALapWithDragAndModelError(geometric, ref, 2 * M_PI / w);
    const double e_indi_drag = flyALapWithDragAndModelError(indi_drag, ref, 2 * M_PI / w);
    std::printf(
        "figure-eight %.0f m/s: rmse geometric %.4f, indi+drag %.4f m; "
        "indi+drag / geometric %.3f\n",
        top_speed, e_geometric, e_indi_drag, e_indi_drag / e_geometric);
    EXPECT_LT(e_indi_drag, 0.5 * e_geometric) << top_speed << " m/s";
    EXPECT_LT(e_indi_drag, 0.01) << top_speed << " m/s";
  }
}
