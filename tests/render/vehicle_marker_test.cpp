// Team markers: a vehicle too small to see at the overview distance gets a ball of a fixed size
// on screen; a large one a halo of its own size.
#include "render/vehicle_marker.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace cosim;

TEST(VehicleMarker, ACrazyflieAcrossARoomGetsASolidBallOfFixedScreenSize) {
  // 16 m away through the 45 degree lens onto 720 rows: 13.25 m visible, 1.84 cm a pixel, so
  // the 5 cm Crazyflie spans 2.7 px.
  const double mpp = metresPerPixel(16.0, 45.0, 720);
  EXPECT_NEAR(mpp, 2.0 * 16.0 * std::tan(22.5 * M_PI / 180.0) / 720.0, 1e-12);
  const VehicleMarker m = vehicleMarker(0.05, 16.0, 45.0, 720);
  EXPECT_TRUE(m.solid);
  EXPECT_NEAR(m.radius / mpp, kMarkerMinPixels, 1e-9);
  // Twice as far: twice as large in metres, the same on screen.
  EXPECT_NEAR(vehicleMarker(0.05, 32.0, 45.0, 720).radius, 2.0 * m.radius, 1e-12);
  // Half the rows (360): each pixel twice as large.
  EXPECT_NEAR(vehicleMarker(0.05, 16.0, 45.0, 360).radius, 2.0 * m.radius, 1e-12);
}

TEST(VehicleMarker, AVehicleLargeEnoughToSeeGetsAHaloOfItsOwnSize) {
  const VehicleMarker m = vehicleMarker(0.35, 5.0, 45.0, 720);  // 61 px across
  EXPECT_FALSE(m.solid);
  EXPECT_DOUBLE_EQ(m.radius, 1.3 * 0.35);
}
