// Reading the sections that say how vehicles move (part of sim/scenario_loader.cpp): planner,
// trajectory and controller at the top level, and under `aerial` for the quadrotors of a
// scenario with ground robots too (the top-level ones then drive the robots).
#include <algorithm>
#include <string>

#include "control/controller_registry.h"
#include "sim/scenario_overrides.h"
#include "sim/scenario_sections.h"

namespace cosim {

namespace {

// Fills a ParamSet with the scalar entries of a mapping, skipping `skip` keys.
void readParams(const YamlReader& r, const YAML::Node& n, const std::string& key,
                const std::vector<std::string>& skip, const std::vector<std::string>& overrides,
                ParamSet& out) {
  r.requireMap(n, key);
  for (const auto& kv : n) {
    const std::string name = kv.first.Scalar();
    bool skipped = false;
    for (const auto& s : skip) skipped = skipped || s == name;
    if (skipped) continue;
    const std::string k = key + "." + name;
    const std::string assignment = overrideBehind(overrides, k, false);
    out.set(name, r.scalar(kv.second, k),
            assignment.empty() ? r.place(kv.second, k) : overridePlace(assignment, k));
  }
}

// planner.separation: {radius: R, height: H}, the ellipsoid a quadrotor team keeps apart.
SeparationEllipsoid readSeparation(const YamlReader& r, const YAML::Node& n,
                                   const std::string& prefix) {
  const std::string key = prefix + "planner.separation";
  r.requireMap(n, key);
  r.checkKeys(n, key, {"radius", "height"});
  if (!n["radius"] || !n["height"]) r.fail(n, key, "needs both 'radius' and 'height' (m)");
  return {r.number(n["radius"], key + ".radius", 0.001, 100.0),
          r.number(n["height"], key + ".height", 0.001, 100.0)};
}

// The planner, trajectory and controller sections under `parent` (the document, or `aerial`),
// into a Scenario or its AerialSections (the same members); `prefix` names their keys.
template <class Sections>
void readMotionSectionsOf(const YamlReader& r, const YAML::Node& parent, const std::string& prefix,
                          const std::vector<std::string>& overrides, Sections& out) {
  if (parent["planner"] && !parent["planner"].IsNull()) {
    const YAML::Node p = parent["planner"];
    r.requireMap(p, prefix + "planner");
    if (!p["name"]) r.fail(p, prefix + "planner", "missing 'name' (e.g. theta_star)");
    out.planner_name = r.text(p["name"], prefix + "planner.name");
    if (p["margin"])
      out.planner_margin = r.number(p["margin"], prefix + "planner.margin", 0.0, 100.0);
    if (p["separation"]) out.planner_separation = readSeparation(r, p["separation"], prefix);
    readParams(r, p, prefix + "planner", {"name", "margin", "separation"}, overrides,
               out.planner_params);
  }

  if (parent["trajectory"]) {
    const YAML::Node t = parent["trajectory"];
    r.requireMap(t, prefix + "trajectory");
    if (t["mode"]) {
      const auto mode = trajectoryModeNamed(r.text(t["mode"], prefix + "trajectory.mode"));
      if (!mode)
        r.fail(t["mode"], prefix + "trajectory.mode", "must be 'waypoints' or 'minimum_snap'");
      out.trajectory_mode = *mode;
    }
    readParams(r, t, prefix + "trajectory", {"mode"}, overrides, out.trajectory_params);
  }

  if (parent["controller"]) {
    const YAML::Node c = parent["controller"];
    r.checkKeys(c, prefix + "controller",
                {"name", "gains", "drag_compensation", "thrust_map", "thrust_map_coefficients",
                 "idle_thrust", "platform"});
    out.controller_given = true;
    if (c["name"]) out.controller_name = r.text(c["name"], prefix + "controller.name");
    const std::string& name = out.controller_name;
    if (const std::string problem = controllerNameProblem(name); !problem.empty())
      r.fail(c["name"], prefix + "controller.name", problem);
    if (c["drag_compensation"]) {
      out.controller_drag_compensation =
          r.boolean(c["drag_compensation"], prefix + "controller.drag_compensation");
      if (out.controller_drag_compensation && !compensatesDrag(name))
        r.fail(
            c["drag_compensation"], prefix + "controller.drag_compensation",
            "applies to the " + dragCompensatingControllers() + " controllers, not '" + name + "'");
    }
    out.controller_thrust_path = readCrazyflieThrustPath(r, c, prefix, name);
    if (c["gains"])
      readParams(r, c["gains"], prefix + "controller.gains", {}, overrides, out.controller_gains);
  }
}

}  // namespace

void readMotionSections(const YamlReader& r, const YAML::Node& root,
                        const std::vector<std::string>& overrides, Scenario& s) {
  readMotionSectionsOf(r, root, "", overrides, s);
  if (root["aerial"]) {
    const YAML::Node n = root["aerial"];
    r.checkKeys(n, "aerial", {"planner", "trajectory", "controller"});
    const auto count = [&s](VehicleKind kind) {
      return std::count_if(s.vehicles.begin(), s.vehicles.end(),
                           [kind](const VehicleSpec& v) { return v.kind == kind; });
    };
    const auto robots = count(VehicleKind::GroundRobot);
    if (robots == 0 || count(VehicleKind::Quadrotor) == 0)
      r.fail(n, "aerial",
             "is for the quadrotors of a scenario with ground robots too (this one has only " +
                 std::string(robots ? "ground robots" : "quadrotors") +
                 "; use the top-level planner, trajectory and controller)");
    readMotionSectionsOf(r, n, "aerial.", overrides, s.aerial);
  }
}

}  // namespace cosim
