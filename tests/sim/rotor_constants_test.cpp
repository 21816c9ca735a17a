// A quadrotor model file must carry its rotor constants (<custom>) and leave the rotor lag to
// sim/: a file that breaks either convention is refused with its name and the place.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>

#include "core/input_error.h"
#include "single_vehicle_scenario.h"

using namespace cosim;

namespace {

// Builds a world whose quad_1500g is models/quad_1500g.xml edited by `edit`; returns the
// InputError's text ("" if it was accepted).
std::string buildWithEditedModel(const std::function<std::string(std::string)>& edit) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("cosim-model-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ifstream in(std::string(COSIM_SOURCE_DIR) + "/models/quad_1500g.xml");
  std::stringstream text;
  text << in.rdbuf();
  std::ofstream(dir / "quad_1500g.xml") << edit(text.str());
  ::setenv("COSIM_MODELS_DIR", dir.c_str(), 1);
  std::string message;
  try {
    WorldModel::build(test::singleVehicleScenario({0, 0, 2}, {0, 0, 2}, 1.0));
  } catch (const InputError& e) {
    message = e.what();
  }
  ::unsetenv("COSIM_MODELS_DIR");
  std::filesystem::remove_all(dir);
  return message;
}

}  // namespace

TEST(RotorConstants, AModelWithoutItsThrustCoefficientIsRefusedNamingIt) {
  const std::string m = buildWithEditedModel([](std::string s) {
    return std::regex_replace(s, std::regex("<numeric name=\"thrust_coefficient\"[^>]*>"), "");
  });
  EXPECT_NE(m.find("quad_1500g.xml"), std::string::npos) << m;
  EXPECT_NE(m.find("<custom>: needs <numeric name=\"thrust_coefficient\">"), std::string::npos)
      << m;
}

TEST(RotorConstants, ARotorConstantOutOfRangeIsRefused) {
  const std::string m = buildWithEditedModel([](std::string s) {
    return std::regex_replace(s, std::regex("name=\"time_constant_down\" data=\"0.025\""),
                              "name=\"time_constant_down\" data=\"-1\"");
  });
  EXPECT_NE(m.find("<numeric name=\"time_constant_down\">: must be one number in"),
            std::string::npos)
      << m;
}

TEST(RotorConstants, AThrustActuatorIsRefusedBecauseTheRotorsAreSims) {
  const std::string m = buildWithEditedModel([](std::string s) {
    return std::regex_replace(s, std::regex("</mujoco>"),
                              "<actuator><general name=\"thrust0\" site=\"rotor0\" "
                              "gear=\"0 0 1 0 0 0.06\"/></actuator></mujoco>");
  });
  EXPECT_NE(m.find("<actuator>: a quadrotor model has no actuators"), std::string::npos) << m;
  EXPECT_EQ(buildWithEditedModel([](std::string s) { return s; }), "");  // the file as it is
}
