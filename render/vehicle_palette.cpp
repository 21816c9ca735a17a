#include "render/vehicle_palette.h"

#include <array>
#include <limits>
#include <vector>

#include "render/colour_difference.h"

namespace cosim {

namespace {

struct Candidate {
  Eigen::Vector3f rgb;
  Eigen::Vector3d lab;
};

std::array<Eigen::Vector3f, kVehiclePaletteSize> choosePalette() {
  // The grid of sRGB colours a vehicle may take: not so light that it fades into the floor
  // (L* 75), not so dark that it reads as black (L* 35), and coloured (chroma 30) so that none
  // looks like the grey obstacles or the dark grey reference.
  std::vector<Candidate> grid;
  for (int r = 0; r < 16; ++r)
    for (int g = 0; g < 16; ++g)
      for (int b = 0; b < 16; ++b) {
        const Eigen::Vector3f rgb(r / 15.0f, g / 15.0f, b / 15.0f);
        const Eigen::Vector3d lab = srgbToLab(rgb);
        if (lab.x() < 35.0 || lab.x() > 75.0 || std::hypot(lab.y(), lab.z()) < 30.0) continue;
        grid.push_back({rgb, lab});
      }
  std::array<Eigen::Vector3f, kVehiclePaletteSize> palette;
  palette[0] = Eigen::Vector3f(0.835f, 0.369f, 0.0f);  // Okabe & Ito's vermillion, #d55e00
  // Each candidate's distance to the nearest colour chosen so far.
  std::vector<double> nearest(grid.size(), std::numeric_limits<double>::infinity());
  Eigen::Vector3d last = srgbToLab(palette[0]);
  for (std::size_t k = 1; k < palette.size(); ++k) {
    std::size_t best = 0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
      nearest[i] = std::min(nearest[i], ciede2000(grid[i].lab, last));
      if (nearest[i] > nearest[best]) best = i;
    }
    palette[k] = grid[best].rgb;
    last = grid[best].lab;
  }
  return palette;
}

}  // namespace

Eigen::Vector3f vehicleColour(std::size_t vehicle) {
  static const std::array<Eigen::Vector3f, kVehiclePaletteSize> palette = choosePalette();
  return palette[vehicle % palette.size()];
}

}  // namespace cosim
