// The error colour scale's top: round numbers, and a floor so calm-air noise looks calm.
#include "render/overlay_palette.h"

#include <gtest/gtest.h>

using namespace cosim;

TEST(OverlayPalette, ErrorScaleRoundsUpToOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(errorScaleMax(0.13), 0.2);
  EXPECT_DOUBLE_EQ(errorScaleMax(0.3), 0.5);
  EXPECT_DOUBLE_EQ(errorScaleMax(0.0004), 0.0005);
}

TEST(OverlayPalette, ErrorScaleNeverGoesBelowAQuarterOfTheGoalTolerance) {
  const double floor = errorScaleFloor(0.2);  // the default goal tolerance
  EXPECT_DOUBLE_EQ(floor, 0.05);
  // Calm air: 0.4 mm of noise no longer fills the whole colour range.
  EXPECT_DOUBLE_EQ(errorScaleMax(0.0004, floor), 0.05);
  // Above the floor the scale follows the data as before.
  EXPECT_DOUBLE_EQ(errorScaleMax(0.13, floor), 0.2);
}

TEST(OverlayPalette, VehicleColoursAreNotColoursOfTheErrorScale) {
  // Every vehicle colour is at least 0.3 (RGB distance) from every point of the error scale,
  // the arrow's magenta and the next vehicle's colour at least 0.25.
  for (std::size_t a = 0; a < 8; ++a) {
    const Eigen::Vector3f c = agentColour(a);
    for (int k = 0; k <= 200; ++k)
      EXPECT_GE((c - errorColour(k / 200.0)).norm(), 0.3f) << "vehicle " << a << " at " << k;
    EXPECT_GE((c - kHeadingColour).norm(), 0.25f) << a;
    EXPECT_GE((c - agentColour(a + 1)).norm(), 0.25f) << a;
  }
  // Before: the palette's yellow was the top of the scale.
  EXPECT_GE((agentColour(6) - errorColour(1.0)).norm(), 0.3f);
}
