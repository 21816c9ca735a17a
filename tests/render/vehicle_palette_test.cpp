// CIEDE2000 against its authors' published test data, and the vehicle palette measured with it.
#include "render/vehicle_palette.h"

#include <gtest/gtest.h>

#include "render/colour_difference.h"
#include "render/overlay_palette.h"

using namespace cosim;

namespace {

struct SharmaPair {
  Eigen::Vector3d lab1, lab2;
  double de00;
};

// Sharma, Wu & Dalal (2005), Table 1: the test pairs and their CIEDE2000 differences (four
// decimals), among them the hue-angle wrap at 0/360 degrees (9-16), the rotation term in the
// blue region (1-6) and near-black and near-white colours.
const SharmaPair kSharmaPairs[] = {
    {{50.0, 2.6772, -79.7751}, {50.0, 0.0, -82.7485}, 2.0425},
    {{50.0, 3.1571, -77.2803}, {50.0, 0.0, -82.7485}, 2.8615},
    {{50.0, 2.8361, -74.0200}, {50.0, 0.0, -82.7485}, 3.4412},
    {{50.0, -1.3802, -84.2814}, {50.0, 0.0, -82.7485}, 1.0000},
    {{50.0, -1.1848, -84.8006}, {50.0, 0.0, -82.7485}, 1.0000},
    {{50.0, -0.9009, -85.5211}, {50.0, 0.0, -82.7485}, 1.0000},
    {{50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}, 2.3669},
    {{50.0, -1.0, 2.0}, {50.0, 0.0, 0.0}, 2.3669},
    {{50.0, 2.49, -0.001}, {50.0, -2.49, 0.0009}, 7.1792},
    {{50.0, 2.49, -0.001}, {50.0, -2.49, 0.0010}, 7.1792},
    {{50.0, 2.49, -0.001}, {50.0, -2.49, 0.0011}, 7.2195},
    {{50.0, 2.49, -0.001}, {50.0, -2.49, 0.0012}, 7.2195},
    {{50.0, -0.001, 2.49}, {50.0, 0.0009, -2.49}, 4.8045},
    {{50.0, -0.001, 2.49}, {50.0, 0.0010, -2.49}, 4.8045},
    {{50.0, -0.001, 2.49}, {50.0, 0.0011, -2.49}, 4.7461},
    {{50.0, -0.001, 2.49}, {50.0, 0.0012, -2.49}, 4.7461},
    {{50.0, 2.5, 0.0}, {50.0, 0.0, -2.5}, 4.3065},
    {{50.0, 2.5, 0.0}, {73.0, 25.0, -18.0}, 27.1492},
    {{50.0, 2.5, 0.0}, {61.0, -5.0, 29.0}, 22.8977},
    {{50.0, 2.5, 0.0}, {56.0, -27.0, -3.0}, 31.9030},
    {{50.0, 2.5, 0.0}, {58.0, 24.0, 15.0}, 19.4535},
    {{50.0, 2.5, 0.0}, {50.0, 3.1736, 0.5854}, 1.0000},
    {{50.0, 2.5, 0.0}, {50.0, 3.2972, 0.0}, 1.0000},
    {{50.0, 2.5, 0.0}, {50.0, 1.8634, 0.5757}, 1.0000},
    {{50.0, 2.5, 0.0}, {50.0, 3.2592, 0.3350}, 1.0000},
    {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
    {{63.0109, -31.0961, -5.8663}, {62.8187, -29.7946, -4.0864}, 1.2630},
    {{61.2901, 3.7196, -5.3901}, {61.4292, 2.2480, -4.9620}, 1.8731},
    {{35.0831, -44.1164, 3.7933}, {35.0232, -40.0716, 1.5901}, 1.8645},
    {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373},
    {{36.4612, 47.8580, 18.3852}, {36.2715, 50.5065, 21.2231}, 1.4146},
    {{90.8027, -2.0831, 1.4410}, {91.1528, -1.6435, 0.0447}, 1.4441},
    {{90.9257, -0.5406, -0.9208}, {88.6381, -0.8985, -0.7239}, 1.5381},
    {{6.7747, -0.2908, -2.4247}, {5.8714, -0.0985, -2.2286}, 0.6377},
    {{2.0776, 0.0795, -1.1350}, {0.9033, -0.0636, -0.5514}, 0.9082},
};

TEST(ColourDifference, Ciede2000MatchesSharmaWuDalalsPublishedPairs) {
  int i = 0;
  for (const SharmaPair& p : kSharmaPairs) {
    ++i;
    // The table gives four decimals.
    EXPECT_NEAR(ciede2000(p.lab1, p.lab2), p.de00, 5e-5) << "pair " << i;
    EXPECT_NEAR(ciede2000(p.lab2, p.lab1), p.de00, 5e-5) << "pair " << i << " reversed";
  }
}

TEST(ColourDifference, SrgbToLabGivesTheKnownValuesOfWhiteAndThePrimaries) {
  EXPECT_NEAR(srgbToLab({1, 1, 1}).x(), 100.0, 0.01);
  EXPECT_NEAR(srgbToLab({1, 1, 1}).y(), 0.0, 0.01);
  const Eigen::Vector3d red = srgbToLab({1, 0, 0});  // L* 53.24, a* 80.09, b* 67.20
  EXPECT_NEAR(red.x(), 53.24, 0.05);
  EXPECT_NEAR(red.y(), 80.09, 0.05);
  EXPECT_NEAR(red.z(), 67.20, 0.05);
  const Eigen::Vector3d blue = srgbToLab({0, 0, 1});  // 32.30, 79.19, -107.86
  EXPECT_NEAR(blue.x(), 32.30, 0.05);
  EXPECT_NEAR(blue.z(), -107.86, 0.05);
}

double smallestDifference(std::size_t count) {
  double smallest = 1e9;
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = i + 1; j < count; ++j)
      smallest =
          std::min(smallest, ciede2000(srgbToLab(vehicleColour(i)), srgbToLab(vehicleColour(j))));
  return smallest;
}

TEST(VehiclePalette, TheFirst32ColoursArePairwiseAtLeast10Ciede2000Apart) {
  EXPECT_GE(smallestDifference(32), 10.0);
}

TEST(VehiclePalette, LargerTeamsStillGetDistinctColoursUpToThePaletteSize) {
  // 64 colours: closer than 32, never the same.
  const double d64 = smallestDifference(kVehiclePaletteSize);
  EXPECT_GT(d64, 4.0);
  EXPECT_LT(d64, smallestDifference(32));
  // Beyond the palette, vehicles kVehiclePaletteSize apart share a colour.
  EXPECT_EQ(vehicleColour(3), vehicleColour(3 + kVehiclePaletteSize));
}

TEST(VehiclePalette, NoVehicleColourIsGreyOrReadsAsTheReferenceOrTheFloor) {
  for (std::size_t i = 0; i < kVehiclePaletteSize; ++i) {
    const Eigen::Vector3d lab = srgbToLab(vehicleColour(i));
    EXPECT_GE(std::hypot(lab.y(), lab.z()), 30.0) << i;
    EXPECT_GE(lab.x(), 35.0) << i;
    EXPECT_LE(lab.x(), 75.0) << i;
    EXPECT_GE(ciede2000(lab, srgbToLab(kReferenceColour)), 10.0) << i;
  }
}

}  // namespace
