// The controller registry: which controllers there are, what each declares (its gains with
// defaults and ranges, its team margin, drag compensation, the Crazyflie thrust path), that the
// declarations are what the controllers read, and that docs/controllers.md shows them as declared.
#include "control/controller_registry.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "closed_loop_flight.h"
#include "control/controller_factory.h"
#include "control/crazyflie_lee_controller.h"
#include "control/geometric_controller.h"
#include "core/input_error.h"
#include "tests/support/input_error_message.h"

namespace cosim {
namespace {

using testing::quad1500g;

std::string messageOf(const std::function<void()>& build) {
  return test::inputErrorMessageOf(build);
}

TEST(ControllerRegistry, ListsTheSevenControllersWithTheirTeamShortfallDragAndThrustPath) {
  struct Expected {
    std::string name;
    double shortfall;
    bool drag, thrust_path;
  };
  const std::vector<Expected> expected = {
      {"cascade", 0.62, false, false},      {"geometric", 0.33, true, false},
      {"indi", 0.02, true, false},          {"dsl_pid", 0.58, false, false},
      {"crazyflie_lee", 0.05, false, true}, {"crazyflie_mellinger", 0.05, false, true},
      {"crazyflie_pid", 0.50, false, true}};
  const auto& entries = ControllerRegistry::instance().entries();
  ASSERT_EQ(entries.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(entries[i].name, expected[i].name);
    EXPECT_DOUBLE_EQ(entries[i].team_shortfall, expected[i].shortfall) << expected[i].name;
    EXPECT_EQ(entries[i].compensates_drag, expected[i].drag) << expected[i].name;
    EXPECT_EQ(entries[i].crazyflie_thrust_path, expected[i].thrust_path) << expected[i].name;
    EXPECT_EQ(compensatesDrag(expected[i].name), expected[i].drag);
    EXPECT_EQ(takesCrazyflieThrustPath(expected[i].name), expected[i].thrust_path);
    // Each builds under its own name.
    ParamSet none("trip.yaml");
    EXPECT_EQ(makeFlightController(entries[i].name, none, quad1500g())->name(), entries[i].name);
  }
  EXPECT_FALSE(compensatesDrag("pid"));
  EXPECT_FALSE(takesCrazyflieThrustPath("crazyflie"));
}

TEST(ControllerRegistry, NameProblemListsTheControllersAndSuggestsTheNearestOne) {
  EXPECT_EQ(controllerNameProblem("indi"), "");
  EXPECT_EQ(controllerNameProblem("geometirc"),
            "must be 'cascade', 'geometric', 'indi', 'dsl_pid', 'crazyflie_lee', "
            "'crazyflie_mellinger' or 'crazyflie_pid' (did you mean 'geometric'?)");
  EXPECT_EQ(controllerNameProblem("lqr").find("did you mean"), std::string::npos);
  EXPECT_EQ(dragCompensatingControllers(), "'geometric' and 'indi'");
}

TEST(ControllerRegistry, AMisspeltGainIsRefusedWithTheNearestDeclaredOne) {
  ParamSet gains("trip.yaml");
  gains.set("k_x_yx", "3", "line 7, key controller.gains.k_x_yx");
  const std::string m = messageOf([&] { makeFlightController("geometric", gains, quad1500g()); });
  EXPECT_NE(m.find("trip.yaml: line 7, key controller.gains.k_x_yx: unknown parameter 'k_x_yx' "
                   "for controller 'geometric' (did you mean 'k_x_xy'?"),
            std::string::npos)
      << m;
}

TEST(ControllerRegistry, AGainOfAnotherControllerIsRefusedNamingWhoseItIs) {
  // pos_kp is the cascade's: given to the geometric controller it is named as the cascade's,
  // with the gains geometric does take, not dropped and not called a misspelling.
  ParamSet gains("trip.yaml");
  gains.set("pos_kp", "2", "line 7, key controller.gains.pos_kp");
  const std::string m = messageOf([&] { makeFlightController("geometric", gains, quad1500g()); });
  EXPECT_NE(m.find("trip.yaml: line 7, key controller.gains.pos_kp: parameter 'pos_kp' does not "
                   "apply to controller 'geometric' (it is a parameter of controller"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("cascade"), std::string::npos) << m;
  EXPECT_NE(m.find("; controller 'geometric' takes: "), std::string::npos) << m;
  EXPECT_NE(m.find("k_x_xy"), std::string::npos) << m;
}

TEST(ControllerRegistry, AGainOutsideItsDeclaredRangeIsRefused) {
  ParamSet gains("trip.yaml");
  gains.set("max_tilt_deg", "90");
  const std::string m = messageOf([&] { makeFlightController("cascade", gains, quad1500g()); });
  EXPECT_NE(m.find("'max_tilt_deg' = 90 is outside [1, 89]"), std::string::npos) << m;
}

// Building from an empty set, a controller asks for exactly its declared keys, with the declared
// defaults and ranges (optional gains, asked for only when given, aside).
TEST(ControllerRegistry, TheDeclaredGainsAreTheOnesEachControllerReads) {
  for (const ControllerEntry& e : ControllerRegistry::instance().entries()) {
    ParamSet probe("probe");
    e.make(quad1500g(), probe, ControllerOptions{});
    std::vector<std::string> read, declared;
    for (const ParamDeclaration& d : probe.declarations())
      read.push_back(d.name + " = " + d.default_value + " " + d.range);
    for (const GainKey& k : gainKeys(e.gains))
      if (k.key != "mass") declared.push_back(k.key + " = " + k.default_text + " " + k.range_text);
    EXPECT_EQ(read, declared) << e.name;
  }
}

TEST(ControllerRegistry, DefaultsAreTheGainStructsInitialisers) {
  const auto& geometric = ControllerRegistry::instance().find("geometric")->gains;
  ASSERT_EQ(geometric.front().name, "k_x");
  EXPECT_EQ(geometric.front().default_value, GeometricGains{}.k_x);
  const std::vector<GainKey> keys = gainKeys(geometric);
  EXPECT_EQ(keys[0].key, "k_x_xy");
  EXPECT_EQ(keys[0].default_text, "6");
  EXPECT_EQ(keys[1].key, "k_x_z");
  EXPECT_EQ(keys[1].default_text, "8");
  EXPECT_EQ(keys[1].doc, "position error -> acceleration, 1/s^2 (z)");
}

TEST(ControllerRegistry, TheBelievedMassIsTheAirframesUnlessGivenAndThenAtLeastTenGrams) {
  const ControllerEntry& lee = *ControllerRegistry::instance().find("crazyflie_lee");
  const GainKey mass = gainKeys(lee.gains).back();
  EXPECT_EQ(mass.key, "mass");
  EXPECT_EQ(mass.default_text, "the airframe's");
  EXPECT_EQ(mass.range_text, "[0.01, 100]");
  ParamSet zero("trip.yaml");
  zero.set("mass", "0");
  EXPECT_NE(messageOf([&] {
              makeFlightController("crazyflie_lee", zero, quad1500g());
            }).find("'mass' = 0 is outside [0.01, 100]"),
            std::string::npos);
}

// The lines of docs/controllers.md's table under "### `NAME`".
std::vector<std::string> documentedTable(const std::string& doc, const std::string& name) {
  std::vector<std::string> rows;
  std::istringstream in(doc);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind("### ", 0) == 0) inside = line == "### `" + name + "`";
    if (inside && line.rfind("|", 0) == 0) rows.push_back(line);
  }
  return rows;
}

// The text of docs/controllers.md under "### `NAME`", to the next heading.
std::string documentedSection(const std::string& doc, const std::string& name) {
  const auto from = doc.find("### `" + name + "`\n");
  if (from == std::string::npos) return "";
  const auto to = doc.find("\n### ", from + 1);
  return doc.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

TEST(ControllerRegistry, DocsGainTablesAreTheDeclarations) {
  std::ifstream file(COSIM_SOURCE_DIR "/docs/controllers.md");
  ASSERT_TRUE(file) << "docs/controllers.md";
  const std::string doc((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  for (const ControllerEntry& e : ControllerRegistry::instance().entries()) {
    std::vector<std::string> expected = {"| gain | default | range | what it does |",
                                         "|---|---|---|---|"};
    for (const GainKey& k : gainKeys(e.gains))
      expected.push_back("| `" + k.key + "` | " + k.default_text + " | " + k.range_text + " | " +
                         k.doc + " |");
    std::string as_text;
    for (const std::string& row : expected) as_text += row + "\n";
    EXPECT_EQ(documentedTable(doc, e.name), expected)
        << "docs/controllers.md, ### `" << e.name << "` should hold:\n"
        << as_text;
    // Its line of properties: the team shortfall, drag compensation, the Crazyflie thrust path.
    std::ostringstream shortfall;
    shortfall << "team shortfall " << e.team_shortfall << " (";
    const std::string section = documentedSection(doc, e.name);
    EXPECT_NE(section.find(shortfall.str()), std::string::npos) << e.name << ": " << section;
    EXPECT_EQ(section.find("takes `drag_compensation`") != std::string::npos, e.compensates_drag)
        << e.name;
    EXPECT_EQ(section.find("Crazyflie thrust path") != std::string::npos, e.crazyflie_thrust_path)
        << e.name;
  }
}

}  // namespace
}  // namespace cosim
