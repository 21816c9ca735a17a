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
  EXPECT_NEAR(p.max_thrust, 6.0, 1e-9);
  EXPECT_NEAR(p.torque_per_thrust, 0.016, 1e-12);
  EXPECT_NEAR(p.rotor_xy[0].norm(), 0.225, 1e-3);
  EXPECT_DOUBLE_EQ(p.spin[0], -p.spin[1]);
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
