#include "sim/scenario_reference.h"

#include <cmath>
#include <cstdio>

#include "control/piecewise_polynomial_reference.h"
#include "control/reference_file.h"
#include "core/input_error.h"
#include "core/input_file.h"

namespace cosim {

namespace {

std::string formatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v == 0.0 ? 0.0 : v);  // no "-0"
  return buf;
}

std::string formatPoint(const Eigen::Vector3d& p) {
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string at -O2.
  std::string text = "(";
  text += formatNumber(p.x());
  text += ", ";
  text += formatNumber(p.y());
  text += ", ";
  text += formatNumber(p.z());
  text += ")";
  return text;
}

// Every point of the reference (sampled every 10 ms, at most 20 000 points) inside the world.
void checkInsideWorld(const YamlReader& r, const YAML::Node& n, const std::string& key,
                      const World& world, const PiecewisePolynomialReference& ref) {
  const std::vector<Eigen::Vector3d> path = ref.sampledPath(20000, 0.01);
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i].allFinite() && world.insideBounds(path[i])) continue;
    const double t = ref.duration() * static_cast<double>(i) / static_cast<double>(path.size() - 1);
    r.fail(n, key,
           "the reference leaves the world bounds at t = " + formatNumber(t) + " s, at " +
               formatPoint(path[i]) + (ref.placement().offset.isZero() ? "" : " (with relative)"));
  }
}

}  // namespace

void readVehicleReference(const YamlReader& r, const YAML::Node& vehicle, const std::string& vkey,
                          const std::filesystem::path& scenario_dir, const Scenario& s,
                          VehicleSpec& v) {
  const YAML::Node n = vehicle["reference"];
  const std::string key = vkey + ".reference";
  r.requireMap(n, key);
  r.checkKeys(n, key, {"file", "timescale", "relative"});
  if (v.kind == VehicleKind::GroundRobot)
    r.fail(n, key, "a given reference is flown by quadrotors; ground robots follow planned paths");
  for (const char* other : {"goal", "waypoints"})
    if (vehicle[other])
      r.fail(vehicle[other], vkey + "." + other,
             "a vehicle with a 'reference' flies it instead of a goal or waypoints (give one)");
  if (!n["file"]) r.fail(n, key, "missing 'file' (a reference CSV)");
  const std::string file = r.text(n["file"], key + ".file");
  v.reference_file =
      std::filesystem::path(file).is_absolute() ? std::filesystem::path(file) : scenario_dir / file;
  ReferencePlacement placement;
  if (n["timescale"]) placement.timescale = r.number(n["timescale"], key + ".timescale", 1e-3, 1e3);
  if (n["relative"] && r.boolean(n["relative"], key + ".relative")) placement.offset = v.start;
  // A run folder's scenario reads the copy its run kept (the original may have moved since).
  if (!s.reference_copies_dir.empty()) {
    const auto copy = s.reference_copies_dir / runReferenceCopyName(s.vehicles.size());
    std::error_code ec;
    if (std::filesystem::is_regular_file(copy, ec)) v.reference_file = copy;
  }
  std::string text;
  try {
    text = readInputFile(v.reference_file.string(), kMaxReferenceFileBytes, "reference file");
  } catch (const InputError& e) {
    r.fail(n["file"], key + ".file", v.reference_file.string() + ": " + e.problem());
  }
  // A defect inside the file is reported at its own line.
  const ReferenceFile read = parseReferenceText(text, v.reference_file.string());
  v.reference_text = std::make_shared<const std::string>(std::move(text));
  auto placed =
      std::make_shared<const PiecewisePolynomialReference>(read.reference.placed(placement));
  if (placed->duration() > kMaxReferenceDuration)
    r.fail(n, key, "the reference lasts more than a day with this timescale");
  checkInsideWorld(r, n, key, s.world, *placed);
  v.waypoints = {placed->at(placed->duration()).position};
  v.reference = std::move(placed);
}

void checkReferenceStarts(const YamlReader& r, const YAML::Node& root, const Scenario& s) {
  for (std::size_t i = 0; i < s.vehicles.size(); ++i) {
    const VehicleSpec& v = s.vehicles[i];
    if (!v.reference) continue;
    const Eigen::Vector3d first = v.reference->at(0.0).position;
    const double gap = (first - v.start).norm();
    if (gap <= s.sim.goal_tolerance) continue;
    const std::string key = "vehicles[" + std::to_string(i) + "].reference";
    r.fail(root["vehicles"][i]["reference"], key,
           "the reference starts at " + formatPoint(first) + ", " + formatNumber(gap) +
               " m from the vehicle's start " + formatPoint(v.start) +
               " (more than sim.goal_tolerance): the vehicle starts at rest at its start; use "
               "relative: true, or a start at the reference's first point");
  }
}

}  // namespace cosim
