// The error colour scale's top: round numbers, and a floor so calm-air noise looks calm.
#include "render/overlay_palette.h"

#include <gtest/gtest.h>

using namespace cosim;

TEST(OverlayPalette, ErrorScaleRoundsUpToAReadableStep) {
  EXPECT_DOUBLE_EQ(errorScaleMax(0.13), 0.15);  // the default run's: 1-2-5 steps gave 0.2
  EXPECT_DOUBLE_EQ(errorScaleMax(0.31), 0.4);
  EXPECT_DOUBLE_EQ(errorScaleMax(0.0007), 0.0008);
  EXPECT_DOUBLE_EQ(errorScaleMax(0.09), 0.1);
  // The largest error always takes at least two thirds of the scale.
  for (double e = 0.011; e < 10.0; e *= 1.37) EXPECT_GE(e / errorScaleMax(e), 2.0 / 3.0) << e;
}

TEST(OverlayPalette, ErrorScaleNeverGoesBelowAQuarterOfTheGoalTolerance) {
  const double floor = errorScaleFloor(0.2);  // the default goal tolerance
  EXPECT_DOUBLE_EQ(floor, 0.05);
  // Calm air: 0.4 mm of noise no longer fills the whole colour range.
  EXPECT_DOUBLE_EQ(errorScaleMax(0.0004, floor), 0.05);
  // Above the floor the scale follows the data.
  EXPECT_DOUBLE_EQ(errorScaleMax(0.13, floor), 0.15);
}

TEST(OverlayPalette, VehiclesMeasuredAgainstTheSameKindOfReferenceShareAScale) {
  // Two robots (timed plan) and a quadrotor (trajectory): the robots' scale is set by the worse
  // robot, the quadrotor's by itself; each at least the floor.
  const std::vector<ErrorReference> refs = {ErrorReference::TimedPlan, ErrorReference::Trajectory,
                                            ErrorReference::TimedPlan};
  const std::vector<std::vector<double>> errors = {{0.01, 0.3}, {0.02, 0.13}, {0.7}};
  const std::vector<double> tops = errorScaleTops(refs, errors, 0.2);
  ASSERT_EQ(tops.size(), 3u);
  EXPECT_DOUBLE_EQ(tops[0], 0.8);
  EXPECT_DOUBLE_EQ(tops[1], 0.15);
  EXPECT_DOUBLE_EQ(tops[2], 0.8);
  // Calm flight: the floor, a quarter of the goal tolerance.
  EXPECT_DOUBLE_EQ(errorScaleTops({ErrorReference::Trajectory}, {{0.001}}, 0.2).at(0), 0.05);
}

TEST(OverlayPalette, TheViewersColoursAreTheRenderersOwn) {
  const nlohmann::json j = visualLanguageJson(3);
  EXPECT_EQ(j["planned"], hexColour(kPlannedPathColour));
  EXPECT_EQ(j["planned"], "#ff4d0d");
  EXPECT_EQ(j["reference"], hexColour(kReferenceColour));
  EXPECT_EQ(j["start"], hexColour(kStartColour));
  EXPECT_EQ(j["goal"], hexColour(kGoalColour));
  ASSERT_EQ(j["vehicles"].size(), 3u);
  EXPECT_EQ(j["vehicles"][2], hexColour(vehicleColour(2)));
  ASSERT_EQ(j["error_stops"].size(), 9u);
  EXPECT_EQ(j["error_stops"][0], hexColour(errorColour(0.0)));  // viridis' dark purple
  EXPECT_EQ(j["error_stops"][8], hexColour(errorColour(1.0)));  // and yellow
}
