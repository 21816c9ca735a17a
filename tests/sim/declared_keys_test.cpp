// The scenario keys are declared once (sim/declared_keys.h) and that one declaration drives the
// loader: its unknown-key list, its type and range checks, the names of its choice keys, and the
// same planner/trajectory/controller keys read at the top level and under `aerial`.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/input_error.h"
#include "sim/declared_key_docs.h"
#include "sim/scenario.h"

namespace cosim {
namespace {

// Two ground robots and a quadrotor: the top-level sections drive the robots, `aerial` the
// quadrotor.
const std::string kMixed =
    "world: {bounds: {min: [0, 0, 0], max: [6, 6, 3]}}\n"
    "vehicles:\n"
    "  - {name: r0, model: omni_base, start: [0.5, 0.5, 0], goal: [5.5, 0.5, 0]}\n"
    "  - {name: r1, model: omni_base, start: [0.5, 5.5, 0], goal: [5.5, 5.5, 0]}\n"
    "  - {name: uav1, model: cf2, start: [1, 3, 1], goal: [5, 3, 1]}\n";

std::string errorOf(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    parseScenario(text, "s.yaml", sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(DeclaredKeys, AerialReadsTheSameDeclarationsAsTheTopLevel) {
  const Scenario s =
      parseScenario(kMixed +
                        "planner: {name: astar, margin: 0.1}\n"
                        "controller: {name: indi}\n"
                        "aerial:\n"
                        "  planner: {name: theta_star, margin: 0.25, resolution: 0.2}\n"
                        "  trajectory: {mode: minimum_snap, max_speed: 1.5}\n"
                        "  controller: {name: geometric, drag_compensation: true}\n",
                    "s.yaml");
  EXPECT_EQ(s.motion.planner.name, "astar");
  EXPECT_DOUBLE_EQ(s.motion.planner.margin, 0.1);
  EXPECT_EQ(s.motion.trajectory.mode, TrajectoryMode::Waypoints);
  EXPECT_TRUE(s.motion.controller.given);
  EXPECT_EQ(s.aerial.planner.name, "theta_star");
  EXPECT_DOUBLE_EQ(s.aerial.planner.margin, 0.25);
  // Declared keys are not handed on as the planner's or the mode's parameters.
  EXPECT_TRUE(s.aerial.planner.params.has("resolution"));
  EXPECT_FALSE(s.aerial.planner.params.has("margin"));
  EXPECT_FALSE(s.aerial.trajectory.params.has("mode"));
  EXPECT_EQ(s.aerial.trajectory.mode, TrajectoryMode::MinimumSnap);
  EXPECT_TRUE(s.aerial.controller.drag_compensation);
  // The same range, named under aerial.
  EXPECT_EQ(errorOf(kMixed + "aerial: {planner: {name: astar, margin: 200}}\n"),
            "s.yaml: line 6, key aerial.planner.margin: = 200 is outside [0, 100]");
  EXPECT_EQ(errorOf(kMixed + "aerial: {trajectory: {mode: teleport}}\n"),
            "s.yaml: line 6, key aerial.trajectory.mode: must be 'waypoints' or 'minimum_snap'");
}

TEST(DeclaredKeys, AChoiceKeyReadsEachDeclaredNameAndRefusesOthers) {
  const std::string uav =
      "world: {bounds: {min: [0, 0, 0], max: [6, 6, 3]}}\n"
      "vehicles: [{name: uav1, model: cf2, start: [1, 3, 1], goal: [5, 3, 1]}]\n"
      "sensors: {preset: mocap}\n";
  for (const auto& [kind, name] : kEstimatorNames) {
    const Scenario s = parseScenario(uav, "s.yaml", {std::string("estimator.name=") + name});
    EXPECT_EQ(s.estimator.kind, kind) << name;
    EXPECT_STREQ(estimatorName(s.estimator.kind), name);
  }
  EXPECT_EQ(errorOf(uav, {"estimator.name=ukf"}),
            "s.yaml: --set estimator.name=ukf, key estimator.name: must be 'ekf', "
            "'crazyflie_kalman' or 'ground_truth'");
}

TEST(DeclaredKeys, TheUnknownKeyListIsTheDeclarationsInOrder) {
  const std::string uav =
      "world: {bounds: {min: [0, 0, 0], max: [6, 6, 3]}}\n"
      "vehicles: [{name: uav1, model: cf2, start: [1, 3, 1], goal: [5, 3, 1]}]\n"
      "disturbances: {gust_ta: 3}\n";
  EXPECT_EQ(errorOf(uav),
            "s.yaml: line 3, key disturbances.gust_ta: unknown key 'gust_ta' (did you mean "
            "'gust_tau'? allowed: rotor_drag, drag, wind, gust, gust_tau, ground_effect, "
            "downwash)");
}

TEST(DeclaredKeys, TheDocsRowsShowTheStructsInitialisersAndTheReadersRanges) {
  const std::vector<DeclaredKeyRow> rows = declaredKeyRows(DisturbanceSettings{});
  ASSERT_EQ(rows.size(), 7u);
  EXPECT_EQ(rows[4].name, "gust_tau");
  EXPECT_EQ(rows[4].default_value, "2");
  EXPECT_EQ(rows[4].range, "[0.01, 1000]");
  EXPECT_EQ(rows[2].type, "[x, y, z]");
  EXPECT_EQ(rows[2].default_value, "[0, 0, 0]");
  EXPECT_EQ(errorOf("world: {bounds: {min: [0, 0, 0], max: [6, 6, 3]}}\n"
                    "vehicles: [{name: uav1, model: cf2, start: [1, 3, 1], goal: [5, 3, 1]}]\n"
                    "disturbances: {drag: 0.1, gust_tau: 0.001}\n"),
            "s.yaml: line 3, key disturbances.gust_tau: = 0.001 is outside [0.01, 1000]");
}

}  // namespace
}  // namespace cosim
