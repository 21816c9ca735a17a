// vehicles[i].airframe: an identified airframe file replaces the model's constants for its
// vehicle (the mass through vehicles[i].mass unless that is given), and bad files are refused
// with the file, line and key.
#include "sim/airframe_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/input_error.h"
#include "sim/scenario.h"
#include "sim/world_model.h"
#include "tests/support/test_files.h"

using namespace cosim;

namespace {

std::string scenarioWith(const std::string& vehicle_extra) {
  return "world: {bounds: {min: [-2, -2, 0], max: [2, 2, 2]}}\n"
         "vehicles:\n"
         "  - {name: cf, model: cf21_brushless, start: [0, 0, 1], goal: [0, 0, 1]" +
         vehicle_extra + "}\n";
}

void write(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

// What cosim identify writes: mappings with value, ci95, residual, unit, samples.
const char* kIdentified =
    "# cosim identify: airframe parameters\n"
    "mass: {value: 0.041, ci95: [0.0408, 0.0412], residual: 0.001, residual_unit: \"kg\", "
    "unit: \"kg\", samples: 100}\n"
    "thrust_coefficient: {value: 3.91e-8, ci95: [3.89e-8, 3.93e-8], residual: 0.01, "
    "residual_unit: \"N\", unit: \"N/(rad/s)^2\", samples: 72}\n"
    "motor_speed_coefficients: {value: [-95.3, 1229.8, -98.96], ci95: [[-121, -69], [1199, "
    "1259], [-107, -90]], residual: 52, residual_unit: \"rad/s\", unit: \"\", samples: 9}\n"
    "motor_delay: 0.002\n"
    "time_constant_up: 0.0425\n"
    "time_constant_down: {value: 0.0426}\n"
    "rotor_drag_coefficient: 2.03e-6\n"
    "gyro_noise: 3.08e-3\n"
    "accel_noise: 1.81e-3\n";

}  // namespace

TEST(AirframeFile, AnIdentifiedFileSetsTheVehiclesRotorConstantsMassAndImuNoise) {
  const auto dir = test::makeFreshDir("airframe_file_applies");
  write(dir / "identified.yaml", kIdentified);
  write(dir / "s.yaml", scenarioWith(", airframe: identified.yaml"));
  const Scenario s = loadScenario((dir / "s.yaml").string());
  ASSERT_EQ(s.vehicles.size(), 1u);
  EXPECT_DOUBLE_EQ(s.vehicles[0].mass, 0.041);  // the identified mass is the flown one
  ASSERT_TRUE(s.vehicles[0].airframe.motor_speed_coefficients);
  EXPECT_DOUBLE_EQ((*s.vehicles[0].airframe.motor_speed_coefficients)[1], 1229.8);
  const WorldModel world = WorldModel::build(s);
  const VehicleHandles& h = world.vehicles()[0];
  EXPECT_NEAR(h.params.mass, 0.041, 1e-12);
  EXPECT_DOUBLE_EQ(h.params.thrust_coefficient, 3.91e-8);  // the model file says 3.86e-8
  EXPECT_DOUBLE_EQ(h.params.motor_delay, 0.002);
  EXPECT_DOUBLE_EQ(h.params.time_constant_up, 0.0425);
  EXPECT_DOUBLE_EQ(h.params.time_constant_down, 0.0426);
  EXPECT_DOUBLE_EQ(h.params.rotor_drag_coefficient, 2.03e-6);
  EXPECT_NEAR(h.params.max_thrust, 3.91e-8 * 2590.0 * 2590.0, 1e-12);  // from the new k_f
  ASSERT_TRUE(h.gyro_noise && h.accel_noise);
  EXPECT_DOUBLE_EQ(*h.gyro_noise, 3.08e-3);
  EXPECT_DOUBLE_EQ(*h.accel_noise, 1.81e-3);
}

TEST(AirframeFile, TheScenariosOwnMassWinsAndAVehicleWithoutOneKeepsTheModel) {
  const auto dir = test::makeFreshDir("airframe_file_mass");
  write(dir / "identified.yaml", kIdentified);
  write(dir / "s.yaml", scenarioWith(", mass: 0.037, airframe: identified.yaml"));
  EXPECT_DOUBLE_EQ(loadScenario((dir / "s.yaml").string()).vehicles[0].mass, 0.037);
  write(dir / "plain.yaml", scenarioWith(""));
  const WorldModel world = WorldModel::build(loadScenario((dir / "plain.yaml").string()));
  EXPECT_DOUBLE_EQ(world.vehicles()[0].params.motor_delay, 0.0);
  EXPECT_DOUBLE_EQ(world.vehicles()[0].params.time_constant_up, 0.015);
  EXPECT_FALSE(world.vehicles()[0].gyro_noise);
}

TEST(AirframeFile, BadFilesNameTheFileTheLineAndTheKey) {
  const auto dir = test::makeFreshDir("airframe_file_bad");
  const auto problem = [&](const std::string& text) -> std::string {
    write(dir / "a.yaml", text);
    try {
      readAirframeFile(dir / "a.yaml");
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), (dir / "a.yaml").string());
      return e.place() + " | " + e.problem();
    }
    return "accepted";
  };
  EXPECT_NE(problem("mass: 0.04\nwingspan: 3\n").find("wingspan"), std::string::npos);
  EXPECT_NE(problem("mass: 0.04\nmotor_delay: -0.1\n").find("line 2, key motor_delay"),
            std::string::npos);
  EXPECT_NE(problem("motor_speed_coefficients: [1, 2]\n").find("three numbers"), std::string::npos);
  EXPECT_NE(problem("mass: {ci95: [1, 2]}\n").find("needs a 'value'"), std::string::npos);
  // A missing airframe file is the scenario's bad input too.
  write(dir / "s.yaml", scenarioWith(", airframe: nowhere.yaml"));
  EXPECT_THROW(loadScenario((dir / "s.yaml").string()), InputError);
}
