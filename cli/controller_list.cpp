#include "cli/controller_list.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "control/controller_registry.h"
#include "run/team_tracking_margin.h"

namespace cosim::cli {

namespace {

std::string padded(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

// "    key = default ([lo, hi])  description", columns aligned within the controller.
std::string gainLines(const std::vector<GainKey>& keys) {
  std::size_t key_width = 0, value_width = 0;
  for (const GainKey& k : keys) {
    key_width = std::max(key_width, k.key.size());
    value_width = std::max(value_width, k.default_text.size() + k.range_text.size() + 3);
  }
  std::string out;
  for (const GainKey& k : keys)
    out += "    " + padded(k.key, key_width) + " = " +
           padded(k.default_text + " (" + k.range_text + ")", value_width) + "  " + k.doc + "\n";
  return out;
}

// "team shortfall 0.62 ellipsoids (a team's plan keeps >= 1.775); takes drag_compensation".
std::string propertiesLine(const ControllerEntry& e) {
  char margin[96];
  std::snprintf(margin, sizeof margin,
                "team shortfall %.4g ellipsoids (a team's plan keeps >= %.4g)", e.team_shortfall,
                teamSeparationFor(e.name, 0.0));
  std::string line = margin;
  if (e.compensates_drag) line += "; takes drag_compensation";
  if (e.crazyflie_thrust_path) line += "; Crazyflie thrust path (thrust_map, ..., platform)";
  return line;
}

}  // namespace

std::string controllerListText() {
  std::string out =
      "Flight controllers (controller.name): set a gain with --set controller.gains.NAME=VALUE or\n"
      "under controller: gains: in the scenario. Shown: name = default (valid range) and what it\n"
      "does; the team shortfall is how much closer than planned two of its vehicles flew, which a\n"
      "quadrotor team's plan keeps in reserve (docs/quadrotor_teams.md).\n";
  for (const ControllerEntry& e : ControllerRegistry::instance().entries())
    out += "\n" + e.name + "  " + e.summary + "\n  " + propertiesLine(e) + "\n" +
           gainLines(gainKeys(e.gains));
  return out;
}

}  // namespace cosim::cli
