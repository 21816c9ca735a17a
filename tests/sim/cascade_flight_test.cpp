// The cascade controller flying the quad_1500g model in MuJoCo: hover and step response.
#include <gtest/gtest.h>

#include "control/cascade_controller.h"
#include "single_vehicle_scenario.h"

using namespace cosim;

namespace {

RunLog fly(const Scenario& s) {
  return test::flyWholeTime(s, [](const QuadrotorParams& q) {
    return std::make_unique<CascadeController>(q, CascadeGains{});
  });
}

}  // namespace

TEST(CascadeFlight, ModelParametersAreReadFromTheMjcf) {
  const WorldModel world = WorldModel::build(test::singleVehicleScenario({0, 0, 2}, {0, 0, 2}, 1));
  const QuadrotorParams& p = world.vehicles()[0].params;
  EXPECT_NEAR(p.mass, 1.5, 1e-9);
  EXPECT_NEAR(p.inertia.z(), 0.055225, 1e-9);
  // PX4's Iris (models/quad_1500g.xml): 5.84e-6 N s^2 x (1100 rad/s)^2 per rotor.
  EXPECT_NEAR(p.max_thrust, 7.0664, 1e-9);
  EXPECT_NEAR(p.torque_per_thrust, 0.06, 1e-12);
  EXPECT_NEAR(p.rotor_xy[0].x(), 0.13, 1e-12);  // front-left rotor
  EXPECT_NEAR(p.rotor_xy[0].y(), 0.22, 1e-12);
  EXPECT_NEAR(p.rotor_z, 0.023, 1e-12);
  EXPECT_DOUBLE_EQ(p.spin[0], -p.spin[1]);
  // The rotor constants of the file's <custom> section.
  EXPECT_DOUBLE_EQ(p.thrust_coefficient, 5.84e-6);
  EXPECT_DOUBLE_EQ(p.time_constant_up, 0.0125);
  EXPECT_DOUBLE_EQ(p.time_constant_down, 0.025);
  EXPECT_DOUBLE_EQ(p.rotor_drag_coefficient, 1.75e-4);
  EXPECT_DOUBLE_EQ(p.propeller_radius, 0.128);
}

TEST(CascadeFlight, HoverHoldsPositionWithinOneCentimetreAfterSettling) {
  const RunLog log = fly(test::singleVehicleScenario({0, 0, 2}, {0, 0, 2}, 8.0));
  const auto& samples = log.vehicles[0].samples;
  double worst = 0.0;
  for (const auto& s : samples)
    if (s.t >= 4.0) worst = std::max(worst, (s.pos - Eigen::Vector3d(0, 0, 2)).norm());
  EXPECT_LT(worst, 0.01);
  EXPECT_TRUE(log.vehicles[0].collisions.empty());
}

TEST(CascadeFlight, OneMetreStepInXSettlesWithUnderTwentyPercentOvershoot) {
  const RunLog log = fly(test::singleVehicleScenario({0, 0, 2}, {1, 0, 2}, 8.0));
  const auto& samples = log.vehicles[0].samples;
  double max_x = 0.0;
  for (const auto& s : samples) max_x = std::max(max_x, s.pos.x());
  EXPECT_LT(max_x - 1.0, 0.2);  // overshoot under 20 % of the step
  EXPECT_GT(max_x, 0.95);       // and it did get there
  EXPECT_NEAR(samples.back().pos.x(), 1.0, 0.01);
  EXPECT_NEAR(samples.back().pos.z(), 2.0, 0.01);
}

TEST(CascadeFlight, NanoQuadHoversWithTheSameDefaultGains) {
  const RunLog log = fly(test::singleVehicleScenario({0, 0, 1}, {0.5, 0, 1}, 8.0, "cf2"));
  EXPECT_NEAR(log.vehicles[0].samples.back().pos.x(), 0.5, 0.01);
  EXPECT_NEAR(log.vehicles[0].samples.back().pos.z(), 1.0, 0.01);
}
