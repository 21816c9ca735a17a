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
