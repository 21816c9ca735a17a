#include "render/overlay_palette.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

namespace cosim {

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
  // Steps whose labels read at a glance; finer than 1-2-5 so that the run's largest error uses
  // most of the scale (0.13 m: 0 to 0.15 m, where 0 to 0.2 m left the flight dark purple).
  for (double m : {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0})
    if (max_error <= m * decade * (1 + 1e-9)) return m * decade;
  return 10 * decade;
}

std::vector<double> errorScaleTops(const std::vector<ErrorReference>& references,
                                   const std::vector<std::vector<double>>& errors,
                                   double goal_tolerance) {
  std::map<ErrorReference, double> largest;  // per kind of reference
  for (std::size_t a = 0; a < references.size(); ++a) {
    double& m = largest[references[a]];
    if (a < errors.size())
      for (double e : errors[a])
        if (std::isfinite(e)) m = std::max(m, e);
  }
  std::vector<double> tops;
  for (ErrorReference r : references)
    tops.push_back(errorScaleMax(largest[r], errorScaleFloor(goal_tolerance)));
  return tops;
}

nlohmann::json visualLanguageJson(std::size_t vehicles) {
  nlohmann::json j;
  j["planned"] = hexColour(kPlannedPathColour);
  j["reference"] = hexColour(kReferenceColour);
  j["flown"] = hexColour(kFlownPathColour);
  j["estimate"] = hexColour(kEstimateColour);
  j["start"] = hexColour(kStartColour);
  j["goal"] = hexColour(kGoalColour);
  j["heading"] = hexColour(kHeadingColour);
  nlohmann::json stops = nlohmann::json::array();
  for (int i = 0; i <= 8; ++i) stops.push_back(hexColour(errorColour(i / 8.0)));
  j["error_stops"] = stops;
  nlohmann::json colours = nlohmann::json::array();
  for (std::size_t v = 0; v < vehicles; ++v) colours.push_back(hexColour(vehicleColour(v)));
  j["vehicles"] = colours;
  return j;
}

}  // namespace cosim
