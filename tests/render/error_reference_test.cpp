// Which reference each vehicle's trail colour measures its error against.
#include <gtest/gtest.h>

#include "render/log_lookup.h"

using namespace cosim;

namespace {
Scenario mixedScenario() {
  Scenario s;
  VehicleSpec robot;
  robot.name = "r0";
  robot.kind = VehicleKind::GroundRobot;
  VehicleSpec uav;
  uav.name = "uav1";
  s.vehicles = {robot, uav};
  s.motion.trajectory.mode = TrajectoryMode::Waypoints;  // the robots' top-level section
  s.aerial.trajectory.mode = TrajectoryMode::MinimumSnap;
  return s;
}
}  // namespace

TEST(ErrorReference, MixedRunMeasuresRobotsAgainstTheirPlanAndQuadrotorsAgainstTheirTrajectory) {
  const Scenario s = mixedScenario();
  EXPECT_EQ(errorReference(s, 0), ErrorReference::TimedPlan);
  // Not the top-level (robots') waypoint mode: the quadrotors fly minimum-snap trajectories.
  EXPECT_EQ(errorReference(s, 1), ErrorReference::Trajectory);
  Scenario flight = s;
  flight.vehicles.erase(flight.vehicles.begin());
  EXPECT_EQ(errorReference(flight, 0), ErrorReference::PlannedPath);  // top-level waypoints
}

TEST(ErrorReference, QuadrotorTrailErrorIsItsDistanceToTheReferenceNotToThePlannedCorner) {
  // A quadrotor 1 mm off its smoothed reference, which cuts the planned path's corner by 0.5 m.
  VehicleLog v;
  v.planned_path = {{0, 0, 2}, {5, 5, 2}, {10, 0, 2}};
  LogSample s;
  s.ref_pos = {5, 4.5, 2};
  s.pos = {5, 4.499, 2};
  v.samples.push_back(s);
  EXPECT_NEAR(trackingErrors(v, ErrorReference::Trajectory)[0], 0.001, 1e-12);
  EXPECT_NEAR(trackingErrors(v, ErrorReference::PlannedPath)[0], 0.501 / std::sqrt(2.0), 1e-9);
}
