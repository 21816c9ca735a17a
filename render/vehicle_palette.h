#pragma once
// One colour per vehicle of a team, the same in the video, the figures and viewer.html: a
// qualitative palette chosen so that each colour is as far as possible (CIEDE2000, render/
// colour_difference.h) from every colour before it.
#include <Eigen/Core>
#include <cstddef>

namespace cosim {

// How many distinct colours the palette holds; vehicle i takes colour i mod kVehiclePaletteSize,
// so in a team of hundreds, vehicles kVehiclePaletteSize apart share a colour.
constexpr std::size_t kVehiclePaletteSize = 64;

// Vehicle i's colour (sRGB, 0..1). The first is Okabe & Ito's vermillion ("Color Universal
// Design", 2008); each next one is, of the sRGB colours on a 16-level grid that stand out on the
// light floor and from the grey obstacles and reference (CIELAB L* 35..75, chroma at least 30),
// the one farthest from all before it (greedy farthest-point selection; ties to the first on the
// grid). The first 32 are at least 10 CIEDE2000 apart (tests/render/vehicle_palette_test.cpp).
Eigen::Vector3f vehicleColour(std::size_t vehicle);

}  // namespace cosim
