// Reading a scenario's `vehicles:` list (part of sim/scenario_loader.cpp): each vehicle's name,
// model (a quadrotor from models/ or a ground robot's URDF), start, goal or waypoints, given
// reference, mass and airframe file.
#include <cstdlib>
#include <string>

#include "sim/scenario_reference.h"
#include "sim/scenario_sections.h"

namespace cosim {

namespace {

constexpr std::size_t kMaxVehicleNameLength = 64;

// Vehicle names: 1 to kMaxVehicleNameLength printable ASCII characters other than space and '/'
// (MuJoCo names are "<vehicle>/<part>"). Commas and quotes are fine (the CSV files quote them);
// line breaks and other control bytes would split a log's rows. "" if `name` is fine.
std::string vehicleNameProblem(const std::string& name) {
  if (name.size() > kMaxVehicleNameLength)
    return "a vehicle name has at most " + std::to_string(kMaxVehicleNameLength) +
           " characters (this one has " + std::to_string(name.size()) + ")";
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte > 0x20 && byte < 0x7f && c != '/') continue;
    // Appended piece by piece: GCC 12's -Wrestrict misfires on operator+ chains.
    std::string why = "vehicle names are printable ASCII without spaces or '/' (this one has ";
    if (byte < 0x20 || byte == 0x7f) {
      why += "a control character";
    } else if (byte >= 0x80) {
      why += "a non-ASCII character";
    } else {
      why += '\'';
      why += c;
      why += '\'';
    }
    why += ')';
    return why;
  }
  return "";
}

void readVehicle(const YamlReader& r, const YAML::Node& n, const std::string& key,
                 const std::filesystem::path& scenario_dir, Scenario& s) {
  r.checkKeys(n, key,
              {"name", "model", "start", "goal", "waypoints", "yaw", "reference", "mass", "airframe",
               "battery", "motor_speed_map"});
  VehicleSpec v;
  v.name =
      n["name"] ? r.text(n["name"], key + ".name") : "uav" + std::to_string(s.vehicles.size() + 1);
  if (const std::string why = vehicleNameProblem(v.name); !why.empty())
    r.fail(n["name"], key + ".name", why);
  for (const auto& other : s.vehicles)
    if (other.name == v.name)
      r.fail(n["name"], key + ".name", "duplicate vehicle name '" + v.name + "'");
  if (!n["model"]) r.fail(n, key, "vehicle needs a 'model' (cf2, quad_1500g, or a URDF path)");
  v.model = r.text(n["model"], key + ".model");
  v.model_file = resolveModelFile(v.model, scenario_dir, v.kind);
  if (!std::filesystem::exists(v.model_file))
    r.fail(n["model"], key + ".model",
           "no model '" + v.model + "' (looked for " + v.model_file.string() + ")");
  if (!n["start"]) r.fail(n, key, "vehicle needs 'start: [x, y, z]'");
  v.start = r.vec3(n["start"], key + ".start");
  checkPointPlacement(r, n["start"], key + ".start", s, v.start);
  if (n["reference"]) readVehicleReference(r, n, key, scenario_dir, s, v);
  if (n["waypoints"]) {
    const YAML::Node w = n["waypoints"];
    if (!w.IsSequence() || w.size() == 0)
      r.fail(w, key + ".waypoints", "must be a non-empty list of [x, y, z] points");
    if (w.size() > kMaxWaypoints) r.fail(w, key + ".waypoints", "too many waypoints");
    for (std::size_t i = 0; i < w.size(); ++i) {
      const std::string k = key + ".waypoints[" + std::to_string(i) + "]";
      v.waypoints.push_back(r.vec3(w[i], k));
      checkPointPlacement(r, w[i], k, s, v.waypoints.back());
    }
  }
  if (n["goal"]) {
    v.waypoints.push_back(r.vec3(n["goal"], key + ".goal"));
    checkPointPlacement(r, n["goal"], key + ".goal", s, v.waypoints.back());
  }
  if (v.waypoints.empty()) r.fail(n, key, "vehicle needs a 'goal', 'waypoints' or a 'reference'");
  if (n["yaw"]) v.yaw_deg = r.number(n["yaw"], key + ".yaw", -3600, 3600);
  if (n["mass"]) {
    if (v.kind == VehicleKind::GroundRobot)
      r.fail(n["mass"], key + ".mass", "mass applies to quadrotor models, not URDFs");
    v.mass = r.number(n["mass"], key + ".mass", 1e-4, 1e4);
  }
  if (n["airframe"]) {
    if (v.kind == VehicleKind::GroundRobot)
      r.fail(n["airframe"], key + ".airframe", "an airframe file applies to quadrotor models");
    const std::filesystem::path p(r.text(n["airframe"], key + ".airframe"));
    v.airframe = readAirframeFile(p.is_absolute() ? p : scenario_dir / p);
    // vehicles[i].mass, when given, is the flown mass; else the identified one.
    if (!n["mass"] && v.airframe.mass) v.mass = *v.airframe.mass;
  }
  readVehiclePower(r, n, key, v);
  s.vehicles.push_back(std::move(v));
}

}  // namespace

std::filesystem::path modelsDirectory() {
  if (const char* env = std::getenv("COSIM_MODELS_DIR"); env && *env) return env;
  return COSIM_MODELS_DIR;
}

std::filesystem::path resolveModelFile(const std::string& model,
                                       const std::filesystem::path& scenario_dir,
                                       VehicleKind& kind) {
  const bool urdf_path = model.size() > 5 && model.substr(model.size() - 5) == ".urdf";
  kind = urdf_path ? VehicleKind::GroundRobot : VehicleKind::Quadrotor;
  if (urdf_path)
    return std::filesystem::path(model).is_absolute() ? std::filesystem::path(model)
                                                      : scenario_dir / model;
  const auto xml = modelsDirectory() / (model + ".xml");
  const auto urdf = modelsDirectory() / (model + ".urdf");
  std::error_code ec;
  if (!std::filesystem::exists(xml, ec) && std::filesystem::exists(urdf, ec)) {
    kind = VehicleKind::GroundRobot;
    return urdf;
  }
  return xml;
}

void readVehiclesSection(const YamlReader& r, const YAML::Node& root,
                         const std::filesystem::path& dir, Scenario& s) {
  if (!root["vehicles"]) r.fail(root, "vehicles", "missing 'vehicles' list");
  const YAML::Node vehicles = root["vehicles"];
  if (!vehicles.IsSequence() || vehicles.size() == 0)
    r.fail(vehicles, "vehicles", "must be a non-empty list");
  if (vehicles.size() > 1000) r.fail(vehicles, "vehicles", "more than 1000 vehicles");
  for (std::size_t i = 0; i < vehicles.size(); ++i)
    readVehicle(r, vehicles[i], "vehicles[" + std::to_string(i) + "]", dir, s);
}

}  // namespace cosim
