// What the program says about its flight controllers: `cosim run --list-controllers` shows each
// controller with its team margin and its gains with the defaults the controllers use, and a
// scenario naming a controller nearly right is told the nearest name.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "tests/support/cosim_command.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

// Whether `block` has the line "    KEY = DEFAULT (RANGE)  DOC", whatever the columns' widths (they
// follow the longest key and value of the controller).
bool listsGain(const std::string& block, const std::string& key, const std::string& value,
               const std::string& doc) {
  const auto escaped = [](const std::string& text) {
    return std::regex_replace(text, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)");
  };
  return std::regex_search(block, std::regex("\n    " + escaped(key) + " * = " +
                                             escaped(value) + " *  " + escaped(doc)));
}

// The lines of `text` from the one starting with `header` to the next empty line.
std::string block(const std::string& text, const std::string& header) {
  const auto from = text.find("\n" + header);
  if (from == std::string::npos) return "";
  const auto to = text.find("\n\n", from + 1);
  return text.substr(from + 1, to == std::string::npos ? std::string::npos : to - from - 1);
}

TEST(ControllerListing, ListsCascadesPositionGainAndTheLeeMassAndTheirTeamMargins) {
  const CommandResult r = runCosim("run --list-controllers");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string cascade = block(r.out, "cascade  ");
  ASSERT_FALSE(cascade.empty()) << r.out;
  EXPECT_NE(cascade.find("team shortfall 0.62 ellipsoids (a team's plan keeps >= 1.775)"),
            std::string::npos)
      << cascade;
  EXPECT_TRUE(listsGain(cascade, "pos_kp", "1 ([0, 100])", "position error -> velocity command"))
      << cascade;
  const std::string geometric = block(r.out, "geometric  ");
  EXPECT_NE(geometric.find("takes drag_compensation"), std::string::npos) << geometric;
  EXPECT_TRUE(listsGain(geometric, "k_x_z", "8 ([0, 10000])", "position error -> acceleration"))
      << geometric;
  const std::string lee = block(r.out, "crazyflie_lee  ");
  EXPECT_NE(lee.find("Crazyflie thrust path"), std::string::npos) << lee;
  EXPECT_TRUE(listsGain(lee, "mass", "the airframe's ([0.01, 100])", "ctrlLee.mass")) << lee;
  for (const char* name : {"indi  ", "dsl_pid  ", "crazyflie_mellinger  ", "crazyflie_pid  "})
    EXPECT_FALSE(block(r.out, name).empty()) << name;
}

TEST(ControllerListing, AMisspeltControllerNameIsToldTheNearestOne) {
  const fs::path dir = freshDir("controller-name");
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml")
      << "world: {bounds: {min: [0, 0, 0], max: [12, 8, 4]}}\n"
         "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [9, 6, 1]}]\n"
         "controller: {name: geometirc}\n";
  const CommandResult r = runCosim("plan " + (dir / "s.yaml").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("line 3, key controller.name: must be 'cascade', 'geometric', 'indi', "
                       "'dsl_pid', 'crazyflie_lee', 'crazyflie_mellinger' or 'crazyflie_pid' (did "
                       "you mean 'geometric'?)"),
            std::string::npos)
      << r.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cosim::test
