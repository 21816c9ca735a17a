// Disturbances act on the flight as modelled, and deterministically.
#include <gtest/gtest.h>

#include "control/geometric_controller.h"
#include "single_vehicle_scenario.h"

using namespace cosim;

namespace {

Scenario hoverScenario(const DisturbanceSettings& d, double seconds) {
  Scenario s = test::singleVehicleScenario({0, 0, 3}, {0, 0, 3}, seconds);
  s.disturbances = d;
  return s;
}

// Hovers at the start under the disturbances, with the integral action switched off so a
// constant force shows up as a steady offset of known size.
RunLog hover(const Scenario& s, double k_i = 0.0) {
  return test::flyWholeTime(s, [k_i](const QuadrotorParams& q) {
    GeometricGains gains;
    gains.k_i = k_i;
    return std::make_unique<GeometricController>(q, gains);
  });
}

}  // namespace

TEST(Disturbances, SteadyWindThroughDragGivesTheExpectedOffset) {
  // Wind 2 m/s along x with drag 0.3 N/(m/s): a steady 0.6 N push. Without integral action the
  // position loop holds it at offset F / (m k_x) = 0.6 / (1.5 * 6) = 0.0667 m.
  DisturbanceSettings d;
  d.drag_coefficient = 0.3;
  d.wind = {2.0, 0.0, 0.0};
  const RunLog log = hover(hoverScenario(d, 6.0));
  const Eigen::Vector3d end = log.vehicles[0].samples.back().pos;
  EXPECT_NEAR(end.x(), 0.6 / (1.5 * 6.0), 0.005);
  EXPECT_NEAR(end.y(), 0.0, 1e-3);
}

TEST(Disturbances, IntegralActionRemovesTheWindOffset) {
  DisturbanceSettings d;
  d.drag_coefficient = 0.3;
  d.wind = {2.0, 0.0, 0.0};
  const RunLog log = hover(hoverScenario(d, 12.0), GeometricGains{}.k_i);
  EXPECT_NEAR(log.vehicles[0].samples.back().pos.x(), 0.0, 0.01);
}

TEST(Disturbances, GustsAreRandomButRepeatableUnderTheSameSeed) {
  DisturbanceSettings d;
  d.drag_coefficient = 0.3;
  d.gust_sigma = 2.0;
  Scenario a = hoverScenario(d, 4.0), b = hoverScenario(d, 4.0), c = hoverScenario(d, 4.0);
  c.sim.seed = 2;
  const Eigen::Vector3d pa = hover(a).vehicles[0].samples.back().pos;
  const Eigen::Vector3d pb = hover(b).vehicles[0].samples.back().pos;
  const Eigen::Vector3d pc = hover(c).vehicles[0].samples.back().pos;
  EXPECT_EQ(pa, pb);                                        // same seed: bit-identical flight
  EXPECT_GT((pa - pc).norm(), 1e-4);                        // another seed: other gusts
  EXPECT_GT((pa - Eigen::Vector3d(0, 0, 3)).norm(), 1e-3);  // and the gusts did push
}

TEST(Disturbances, GroundEffectLiftsAVehicleHoveringLow) {
  // At 0.25 m over the floor (rotor hubs 0.273 m) with 0.128 m rotors, thrust grows by
  // 1/(1 - (0.128/1.092)^2) - 1 = 1.4 %;
  // without integral action the hover settles higher by 1.4 % of m g / (m k_z) = 0.137/8 m.
  DisturbanceSettings d;
  d.ground_effect = true;
  Scenario s = hoverScenario(d, 5.0);
  s.vehicles[0].start = {0, 0, 0.25};
  s.vehicles[0].waypoints = {{0, 0, 0.25}};
  const double z = hover(s).vehicles[0].samples.back().pos.z();
  EXPECT_GT(z - 0.25, 0.005);
  EXPECT_LT(z - 0.25, 0.05);
}
