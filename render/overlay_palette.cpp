#include "render/overlay_palette.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace cosim {

Eigen::Vector3f agentColour(std::size_t agent) {
  // Reds, purples, a light blue and a grey: none near the viridis error scale's purple, blue, teal,
  // green or yellow (at least 0.3 apart in RGB from every point of it), neighbours apart.
  static const std::array<Eigen::Vector3f, 8> palette = {
      Eigen::Vector3f{0.84f, 0.37f, 0.0f},   // vermillion (Okabe & Ito)
      Eigen::Vector3f{0.34f, 0.71f, 0.91f},  // sky blue (Okabe & Ito)
      Eigen::Vector3f{0.80f, 0.47f, 0.65f},  // reddish purple (Okabe & Ito)
      Eigen::Vector3f{0.62f, 0.10f, 0.42f},  // plum (Okabe & Ito's orange lit up read as yellow)
      Eigen::Vector3f{0.75f, 0.08f, 0.16f},  // crimson
      Eigen::Vector3f{1.0f, 0.62f, 0.80f},   // pink
      Eigen::Vector3f{0.55f, 0.30f, 0.12f},  // brown
      Eigen::Vector3f{0.50f, 0.50f, 0.50f},  // grey
  };
  return palette[agent % palette.size()];
}

Eigen::Vector3f errorColour(double fraction) {
  // viridis sampled at 0, 0.25, 0.5, 0.75, 1 and interpolated linearly in between.
  static const std::array<Eigen::Vector3f, 5> stops = {
      Eigen::Vector3f{0.267f, 0.005f, 0.329f}, Eigen::Vector3f{0.230f, 0.322f, 0.546f},
      Eigen::Vector3f{0.128f, 0.567f, 0.551f}, Eigen::Vector3f{0.369f, 0.789f, 0.383f},
      Eigen::Vector3f{0.993f, 0.906f, 0.144f}};
  const double f =
      std::clamp(std::isfinite(fraction) ? fraction : 1.0, 0.0, 1.0) * (stops.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(f), stops.size() - 2);
  const float w = static_cast<float>(f - i);
  return (1.0f - w) * stops[i] + w * stops[i + 1];
}

std::string hexColour(const Eigen::Vector3f& rgb) {
  char buf[8];
  const auto byte = [](float c) {
    return static_cast<int>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255));
  };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(rgb.x()), byte(rgb.y()), byte(rgb.z()));
  return buf;
}

double errorScaleFloor(double goal_tolerance) {
  return 0.25 * goal_tolerance;
}

double errorScaleMax(double max_error, double floor) {
  if (std::isfinite(floor)) max_error = std::max(max_error, floor);
  if (!(max_error > 1e-6)) return 0.1;
  const double decade = std::pow(10.0, std::floor(std::log10(max_error)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (max_error <= m * decade * (1 + 1e-9)) return m * decade;
  return 10 * decade;
}

}  // namespace cosim
