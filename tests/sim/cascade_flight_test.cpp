// The cascade controller flying the quad_1500g model in MuJoCo: hover and step response.
#include <gtest/gtest.h>

#include "control/cascade_controller.h"
#include "control/waypoint_reference.h"
#include "sim/flight_simulation.h"
#include "sim/world_model.h"

using namespace cosim;

namespace {

Scenario emptyWorld(const Eigen::Vector3d& start, const Eigen::Vector3d& goal, double seconds,
                    const std::string& model = "quad_1500g") {
  Scenario s;
  s.file = "test";
  s.world.bounds_min = {-10, -10, 0};
  s.world.bounds_max = {10, 10, 10};
  VehicleSpec v;
  v.name = "uav1";
  v.model = model;
  v.model_file = modelsDirectory() / (model + ".xml");
  v.start = start;
  v.waypoints = {goal};
  s.vehicles.push_back(v);
  s.sim.max_time = seconds;
  return s;
}

RunLog fly(const Scenario& s) {
  const WorldModel world = WorldModel::build(s);
  CascadeController controller(world.vehicles()[0].params, CascadeGains{});
  WaypointReference reference({s.vehicles[0].goal()}, 0.0);
  std::vector<VehiclePilot> pilots(1);
  pilots[0].controller = &controller;
  pilots[0].reference = &reference;
  pilots[0].goal = s.vehicles[0].goal();
  FlightOptions options;
  options.settings = s.sim;
  options.hold_after_arrival = 1e9;  // fly the whole max_time
  return simulateFlight(world, s, pilots, options);
}

}  // namespace

TEST(CascadeFlight, ModelParametersAreReadFromTheMjcf) {
  const WorldModel world = WorldModel::build(emptyWorld({0, 0, 2}, {0, 0, 2}, 1));
  const QuadrotorParams& p = world.vehicles()[0].params;
  EXPECT_NEAR(p.mass, 1.5, 1e-9);
  EXPECT_NEAR(p.inertia.z(), 0.055225, 1e-9);
  EXPECT_NEAR(p.max_thrust, 6.0, 1e-9);
  EXPECT_NEAR(p.torque_per_thrust, 0.016, 1e-12);
  EXPECT_NEAR(p.rotor_xy[0].norm(), 0.225, 1e-3);
  EXPECT_DOUBLE_EQ(p.spin[0], -p.spin[1]);
}

TEST(CascadeFlight, HoverHoldsPositionWithinOneCentimetreAfterSettling) {
  const RunLog log = fly(emptyWorld({0, 0, 2}, {0, 0, 2}, 8.0));
  const auto& samples = log.vehicles[0].samples;
  double worst = 0.0;
  for (const auto& s : samples)
    if (s.t >= 4.0) worst = std::max(worst, (s.pos - Eigen::Vector3d(0, 0, 2)).norm());
  EXPECT_LT(worst, 0.01);
  EXPECT_TRUE(log.vehicles[0].collisions.empty());
}

TEST(CascadeFlight, OneMetreStepInXSettlesWithUnderTwentyPercentOvershoot) {
  const RunLog log = fly(emptyWorld({0, 0, 2}, {1, 0, 2}, 8.0));
  const auto& samples = log.vehicles[0].samples;
  double max_x = 0.0;
  for (const auto& s : samples) max_x = std::max(max_x, s.pos.x());
  EXPECT_LT(max_x - 1.0, 0.2);  // overshoot under 20 % of the step
  EXPECT_GT(max_x, 0.95);       // and it did get there
  EXPECT_NEAR(samples.back().pos.x(), 1.0, 0.01);
  EXPECT_NEAR(samples.back().pos.z(), 2.0, 0.01);
}

TEST(CascadeFlight, NanoQuadHoversWithTheSameDefaultGains) {
  const RunLog log = fly(emptyWorld({0, 0, 1}, {0.5, 0, 1}, 8.0, "cf2"));
  EXPECT_NEAR(log.vehicles[0].samples.back().pos.x(), 0.5, 0.01);
  EXPECT_NEAR(log.vehicles[0].samples.back().pos.z(), 1.0, 0.01);
}
