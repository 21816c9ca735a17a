// The Foxglove layout written beside an MCAP export: which panels, on which topics, and topic
// names Foxglove's message paths can read whatever the vehicle is called.
#include "run/foxglove_layout.h"

#include <gtest/gtest.h>

using namespace cosim;

TEST(FoxgloveLayout, PlotsTheFirstVehiclesPositionAndErrorsAndLooksAtTheWholeWorld) {
  const std::vector<std::string> names = {"a", "b", "c", "d", "e", "f"};
  const auto layout = foxgloveLayout(names, {0, 0, 0}, {40, 30, 8});
  const auto& position = layout.at("configById").at("Plot!position").at("paths");
  const auto& error = layout.at("configById").at("Plot!error").at("paths");
  // Four vehicles plotted of six: x, y, z each; tracking and estimation error each.
  EXPECT_EQ(position.size(), 3 * kFoxgloveLayoutPlottedVehicles);
  EXPECT_EQ(error.size(), 2 * kFoxgloveLayoutPlottedVehicles);
  EXPECT_EQ(position[4].at("value"), "/vehicles/b/state.position.y");
  EXPECT_EQ(error[3].at("value"), "/vehicles/b/state.estimate_error_m");
  const auto& camera = layout.at("configById").at("3D!cosim").at("cameraState");
  EXPECT_EQ(camera.at("targetOffset"), (nlohmann::json{20.0, 15.0, 4.0}));
  EXPECT_NEAR(camera.at("distance").get<double>(), std::sqrt(40.0 * 40 + 30 * 30 + 8 * 8), 1e-9);
  EXPECT_EQ(foxgloveLayoutPathFor("/runs/x/run.mcap"), "/runs/x/run.layout.json");
}

TEST(FoxgloveLayout, TopicsWithOtherCharactersAreQuotedInMessagePaths) {
  EXPECT_EQ(foxgloveMessagePath("/vehicles/uav-1_a/state", "error_m"),
            "/vehicles/uav-1_a/state.error_m");
  EXPECT_EQ(foxgloveMessagePath("/vehicles/uav 1/state", "error_m"),
            "\"/vehicles/uav 1/state\".error_m");
  EXPECT_EQ(foxgloveMessagePath("/vehicles/a\"b/state", "position.x"),
            "\"/vehicles/a\\\"b/state\".position.x");
}
