// Reading the sections that say how vehicles move (part of sim/scenario_loader.cpp): planner,
// trajectory and controller at the top level, and under `aerial` for the quadrotors of a
// scenario with ground robots too (the top-level ones then drive the robots).
#include <algorithm>
#include <string>

#include "control/controller_registry.h"
#include "sim/declared_key_reader.h"
#include "sim/scenario_overrides.h"
#include "sim/scenario_sections.h"

namespace cosim {

namespace {

// Fills a ParamSet with the scalar entries of a mapping, skipping `skip` keys; the names that
// overrides set go to `from_overrides`, if given.
void readParams(const YamlReader& r, const YAML::Node& n, const std::string& key,
                const std::vector<std::string>& skip, const std::vector<std::string>& overrides,
                ParamSet& out, std::vector<std::string>* from_overrides = nullptr) {
  r.requireMap(n, key);
  for (const auto& kv : n) {
    const std::string name = kv.first.Scalar();
    bool skipped = false;
    for (const auto& s : skip) skipped = skipped || s == name;
    if (skipped) continue;
    const std::string k = key + "." + name;
    const std::string assignment = overrideBehind(overrides, k, false);
    if (from_overrides && !assignment.empty()) from_overrides->push_back(name);
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
// read through their declared keys (sim/motion_sections.h); `prefix` names their keys. The keys
// a section does not declare are its planner's or mode's parameters.
void readMotionSectionsOf(const YamlReader& r, const YAML::Node& parent, const std::string& prefix,
                          const std::vector<std::string>& overrides, MotionSections& out) {
  if (parent["planner"] && !parent["planner"].IsNull()) {
    const YAML::Node p = parent["planner"];
    const std::string key = prefix + "planner";
    r.requireMap(p, key);
    if (!p["name"]) r.fail(p, key, "missing 'name' (e.g. theta_star)");
    DeclaredKeyReader reader(r, p, key);
    out.planner.declareKeys(reader);
    if (p["separation"]) out.planner.separation = readSeparation(r, p["separation"], prefix);
    readParams(r, p, key, declaredKeyNames(out.planner), overrides, out.planner.params,
               &out.planner.params_from_overrides);
    out.planner.name_from_override = !overrideBehind(overrides, key + ".name", false).empty();
  }

  if (parent["trajectory"]) {
    const YAML::Node t = parent["trajectory"];
    const std::string key = prefix + "trajectory";
    r.requireMap(t, key);
    DeclaredKeyReader reader(r, t, key);
    out.trajectory.declareKeys(reader);
    readParams(r, t, key, declaredKeyNames(out.trajectory), overrides, out.trajectory.params);
  }

  if (parent["controller"]) {
    const YAML::Node c = parent["controller"];
    ControllerSection& controller = out.controller;
    readDeclaredKeys(r, c, prefix + "controller", controller);
    controller.given = true;
    const std::string& name = controller.name;
    if (const std::string problem = controllerNameProblem(name); !problem.empty())
      r.fail(c["name"], prefix + "controller.name", problem);
    if (controller.drag_compensation && !compensatesDrag(name))
      r.fail(
          c["drag_compensation"], prefix + "controller.drag_compensation",
          "applies to the " + dragCompensatingControllers() + " controllers, not '" + name + "'");
    controller.thrust_path = readCrazyflieThrustPath(r, c, prefix, name);
    if (c["gains"])
      readParams(r, c["gains"], prefix + "controller.gains", {}, overrides, controller.gains);
  }
}

}  // namespace

void readMotionSections(const YamlReader& r, const YAML::Node& root,
                        const std::vector<std::string>& overrides, Scenario& s) {
  readMotionSectionsOf(r, root, "", overrides, s.motion);
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
