// What a scenario says about a real Crazyflie: vehicles[i].mass (the flown total mass, inertia
// scaled with it) and the firmware controllers' loop-rate requirement.
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "sim/scenario.h"
#include "sim/world_model.h"
#include "tests/sim/single_vehicle_scenario.h"

namespace cosim {
namespace {

const char* kCrazyflie = R"(world:
  bounds: {min: [-2, -2, 0], max: [2, 2, 2]}
vehicles:
  - {name: cf, model: cf21_brushless, mass: 0.037, start: [0, 0, 1], goal: [0, 0, 1]}
controller: {name: crazyflie_lee}
sim: {control_rate: 500}
)";

std::string errorOf(const std::string& text) {
  try {
    parseScenario(text, "s.yaml", {});
  } catch (const InputError& e) {
    return e.place() + " | " + e.problem();
  }
  return "";
}

std::string with(std::string s, const std::string& from, const std::string& to) {
  return s.replace(s.find(from), from.size(), to);
}

TEST(CrazyflieSetup, MassSetsTheTotalAndScalesTheInertiaAtConstantRadiusOfGyration) {
  Scenario s = test::singleVehicleScenario({0, 0, 1}, {0, 0, 1}, 1.0, "cf21_brushless");
  const QuadrotorParams bare = WorldModel::build(s).vehicles()[0].params;
  EXPECT_NEAR(bare.mass, 0.032, 1e-12);  // models/cf21_brushless.xml
  s.vehicles[0].mass = 0.037;
  const QuadrotorParams flown = WorldModel::build(s).vehicles()[0].params;
  EXPECT_NEAR(flown.mass, 0.037, 1e-12);
  // 2.3205e-5 x 37 / 32 = 2.68308e-5 kg m^2, and the same ratio on the other axes.
  EXPECT_NEAR(flown.inertia.x(), 2.68308e-5, 1e-9);
  EXPECT_NEAR(flown.inertia.z() / bare.inertia.z(), 0.037 / 0.032, 1e-9);
  // The rotors do not change with the payload.
  EXPECT_EQ(flown.max_thrust, bare.max_thrust);
}

TEST(CrazyflieSetup, LoaderReadsMassAndTheFirmwareControllers) {
  const Scenario s = parseScenario(kCrazyflie, "s.yaml", {});
  EXPECT_EQ(s.vehicles[0].mass, 0.037);
  EXPECT_EQ(s.motion.controller.name, "crazyflie_lee");
  EXPECT_NE(errorOf(with(kCrazyflie, "mass: 0.037", "mass: -1")).find("vehicles[0].mass"),
            std::string::npos);
}

TEST(CrazyflieSetup, FirmwareControllersNeedAMultipleOfFiveHundredHertz) {
  const std::string e = errorOf(with(kCrazyflie, "control_rate: 500", "control_rate: 250"));
  EXPECT_NE(e.find("sim.control_rate"), std::string::npos) << e;
  EXPECT_NE(e.find("500 Hz"), std::string::npos) << e;
  EXPECT_EQ(errorOf(with(kCrazyflie, "control_rate: 500", "control_rate: 1000")), "");
}

}  // namespace
}  // namespace cosim
