#include <algorithm>

#include "render/run_renderer.h"

// The legend of a rendered frame: which lines and markers the frame draws, in as many entries
// as it has room for.

namespace cosim {

std::vector<LegendEntry> RunRenderer::legendEntries(std::size_t room, bool compact) const {
  std::vector<LegendEntry> legend;
  const std::size_t n = log_.vehicles.size();
  const bool plans = n == 1 || scenario_.render.team_plans;
  const bool has_reference = plans && std::find(references_.begin(), references_.end(),
                                                ErrorReference::Trajectory) != references_.end();
  if (compact) {
    // Three short lines: the path (or the vehicles' colours), the reference, the error.
    if (n == 1) {
      legend.push_back({"plan", kPlannedPathColour});
    } else {
      LegendEntry all{plans ? "plans" : "vehicles", vehicleColour(0)};
      for (std::size_t a = 0; a < n && a < 8; ++a) all.stripes.push_back(vehicleColour(a));
      legend.push_back(all);
    }
    if (has_reference) legend.push_back({"reference", kReferenceColour});
    if (trailsShowError()) legend.push_back({"flown (error)", errorColour(0.6), /*gradient=*/true});
    return legend;
  }
  if (n == 1) {
    legend.push_back({"planned path", kPlannedPathColour});
  } else if (!plans) {
    LegendEntry all{trailsShowError() ? "vehicles, starts and goals (one colour each)"
                                      : "flown paths, starts and goals (one colour each)",
                    vehicleColour(0)};
    for (std::size_t a = 0; a < n && a < 8; ++a) all.stripes.push_back(vehicleColour(a));
    legend.push_back(all);
  } else if (n + 1 + (has_reference ? 1 : 0) > room) {
    // A small frame: every vehicle's planned path in one striped entry.
    LegendEntry all{"planned paths (one colour each)", vehicleColour(0)};
    for (std::size_t a = 0; a < n && a < 8; ++a) all.stripes.push_back(vehicleColour(a));
    legend.push_back(all);
  } else if (n <= 6) {
    for (std::size_t a = 0; a < n; ++a)
      legend.push_back({log_.vehicles[a].name + " planned", vehicleColour(a)});
  } else {
    // Many vehicles: the quadrotors by name (the first four), the robots as one striped entry.
    LegendEntry robots{"robots planned (one colour each)", vehicleColour(0)};
    LegendEntry others{"more quadrotors planned", vehicleColour(0)};
    std::size_t named = 0;
    for (std::size_t a = 0; a < n; ++a) {
      if (isGround(a)) {
        if (robots.stripes.size() < 8) robots.stripes.push_back(vehicleColour(a));
      } else if (named < 4) {
        legend.push_back({log_.vehicles[a].name + " planned", vehicleColour(a)});
        ++named;
      } else if (others.stripes.size() < 8) {
        others.stripes.push_back(vehicleColour(a));
      }
    }
    if (!others.stripes.empty()) legend.push_back(others);
    if (!robots.stripes.empty()) legend.push_back(robots);
  }
  if (has_reference) legend.push_back({"reference trajectory (dashed)", kReferenceColour});
  if (trailsShowError())
    legend.push_back({scales_.size() == 1 ? std::string("flown path (colour = error to ") +
                                                errorReferenceName(scales_[0].reference) + ")"
                                          : "flown paths (colour = error, scales at right)",
                      errorColour(0.6), /*gradient=*/true});
  if (n == 1) {
    legend.push_back({"start", kStartColour});
    legend.push_back({"goal", kGoalColour});
  }
  return legend;
}

}  // namespace cosim
