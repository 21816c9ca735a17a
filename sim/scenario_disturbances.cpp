// Reading a scenario's `disturbances:` section (part of sim/scenario_loader.cpp): what the air
// and the ground do to the quadrotors (sim/disturbance_settings.h).
#include <string>

#include "sim/scenario_sections.h"

namespace cosim {

void readDisturbancesSection(const YamlReader& r, const YAML::Node& root, Scenario& s) {
  if (root["disturbances"]) {
    const YAML::Node n = root["disturbances"];
    r.checkKeys(n, "disturbances",
                {"rotor_drag", "drag", "wind", "gust", "gust_tau", "ground_effect", "downwash"});
    DisturbanceSettings& d = s.disturbances;
    if (n["rotor_drag"]) d.rotor_drag = r.boolean(n["rotor_drag"], "disturbances.rotor_drag");
    if (n["drag"]) d.drag_coefficient = r.number(n["drag"], "disturbances.drag", 0.0, 100.0);
    if (n["wind"]) {
      d.wind = r.vec3(n["wind"], "disturbances.wind");
      if (d.wind.norm() > 50.0) r.fail(n["wind"], "disturbances.wind", "wind above 50 m/s");
    }
    if (n["gust"]) d.gust_sigma = r.number(n["gust"], "disturbances.gust", 0.0, 50.0);
    if (n["gust_tau"]) d.gust_tau = r.number(n["gust_tau"], "disturbances.gust_tau", 0.01, 1000.0);
    if (n["ground_effect"])
      d.ground_effect = r.boolean(n["ground_effect"], "disturbances.ground_effect");
    if (n["downwash"]) d.downwash = r.boolean(n["downwash"], "disturbances.downwash");
    // The air moves a vehicle only through drag: wind without a drag term would do nothing.
    if (d.hasWind() && !d.hasDrag())
      r.fail(n["wind"] ? n["wind"] : n["gust"],
             n["wind"] ? "disturbances.wind" : "disturbances.gust",
             "wind acts through drag and this scenario has none: add rotor_drag: true (the "
             "airframe's per-rotor drag) or drag: K (N per m/s)");
  }
}

}  // namespace cosim
