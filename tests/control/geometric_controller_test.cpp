#include "control/geometric_controller.h"

#include <gtest/gtest.h>

#include <cmath>

#include "control/cascade_controller.h"
#include "control/indi_controller.h"
#include "tests/control/closed_loop_flight.h"

using namespace cosim;
using namespace cosim::testing;
using Eigen::Vector3d;

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

TEST(GeometricController, DragCompensationTiltsIntoTheReferenceVelocity) {
  // Level, on the reference and moving with it at 5 m/s: only the drag term R D R^T v_ref asks
  // for a tilt, atan(d 5 / g) forward (d = 0.37 1/s for the Iris: 10.7 degrees).
  const QuadrotorParams p = quad1500g();
  const double d = p.linearDragPerMass().x();
  FlatReference ref;
  ref.position = Vector3d(0, 0, 3);
  ref.velocity = Vector3d(5, 0, 0);
  VehicleState s;
  s.position = ref.position;
  s.velocity = ref.velocity;
  for (bool drag : {false, true}) {
    GeometricController controller(p, {}, drag);
    const ControlOutput out = controller.update(s, ref, 0.002);
    const Vector3d b3d = controller.desiredAttitude().col(2);
    const double expected = drag ? std::atan(d * 5.0 / p.gravity) : 0.0;
    EXPECT_NEAR(std::atan2(b3d.x(), b3d.z()), expected, 1e-9) << drag;
    EXPECT_NEAR(out.collective_thrust, p.mass * p.gravity, 1e-9) << drag;  // along current z
  }
  EXPECT_NEAR(std::atan(d * 5.0 / p.gravity) * 180.0 / M_PI, 10.7, 0.1);
}

TEST(GeometricController, DragCompensationReducesTheErrorOfAFastCircle) {
  // 8 m radius at 6 and 8 m/s with rotor drag and the model error: the drag feed-forward takes
  // most of the lag out (measured: 0.36 -> 0.09 m at 6 m/s, 0.46 -> 0.15 m at 8 m/s; the rest is
  // the model error, which only the integral, slow and gated to near-steady states, works on).
  const Vector3d c(0, 0, 3);
  for (double speed : {6.0, 8.0}) {
    const double w = speed / 8.0;
    const auto ref = [&](double t) { return circle(t, 8.0, w, c); };
    GeometricController plain(quad1500g()), compensated(quad1500g(), {}, true);
    const double e_plain = flyALapWithDragAndModelError(plain, ref, 2 * M_PI / w);
    const double e_compensated = flyALapWithDragAndModelError(compensated, ref, 2 * M_PI / w);
    EXPECT_LT(e_compensated, 0.4 * e_plain)
        << speed << " m/s: " << e_compensated << " vs " << e_plain;
  }
}

TEST(GeometricController, DragCorrectedBodyRatesAreThoseOfTheFlatAttitude) {
  // On the reference, in its flat attitude, at 8 m/s round a circle under drag: the desired
  // roll and pitch rates are the flatness rates with drag (IndiController::feedForward, itself
  // checked against differences of the flat attitude), not the drag-free ones.
  const QuadrotorParams p = quad1500g();
  const Vector3d D = p.linearDragPerMass();
  const FlatReference ref = circle(0.7, 8.0, 1.0, Vector3d(0, 0, 3));
  Eigen::Matrix3d R;
  double c;
  flatAttitude(ref, D.x(), p.gravity, &R, &c);
  VehicleState s;
  s.position = ref.position;
  s.velocity = ref.velocity;
  s.attitude = Eigen::Quaterniond(R);
  GeometricController controller(p, {}, true);
  controller.update(s, ref, 0.002);
  EXPECT_LT((controller.desiredAttitude() - R).norm(), 1e-9);
  const Vector3d with_drag = IndiController::feedForward(R, c, ref, D).omega;
  const Vector3d without = IndiController::feedForward(R, c, ref, Vector3d::Zero()).omega;
  EXPECT_LT((controller.desiredBodyRates().head<2>() - with_drag.head<2>()).norm(), 1e-9);
  EXPECT_GT((with_drag - without).head<2>().norm(), 0.1)  // the drag terms matter here
      << with_drag.transpose() << " vs " << without.transpose();
}
