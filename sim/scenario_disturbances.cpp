// Reading a scenario's `disturbances:` section (part of sim/scenario_loader.cpp): what the air
// and the ground do to the quadrotors (sim/disturbance_settings.h declares the keys).
#include <string>

#include "sim/declared_key_reader.h"
#include "sim/scenario_sections.h"

namespace cosim {

void readDisturbancesSection(const YamlReader& r, const YAML::Node& root, Scenario& s) {
  if (!root["disturbances"]) return;
  const YAML::Node n = root["disturbances"];
  DisturbanceSettings& d = s.disturbances;
  readDeclaredKeys(r, n, "disturbances", d);
  if (d.wind.norm() > kMaxWindSpeed) r.fail(n["wind"], "disturbances.wind", "wind above 50 m/s");
  // The air moves a vehicle only through drag: wind without a drag term would do nothing.
  if (d.hasWind() && !d.hasDrag())
    r.fail(n["wind"] ? n["wind"] : n["gust"], n["wind"] ? "disturbances.wind" : "disturbances.gust",
           "wind acts through drag and this scenario has none: add rotor_drag: true (the "
           "airframe's per-rotor drag) or drag: K (N per m/s)");
}

}  // namespace cosim
