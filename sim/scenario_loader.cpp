#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "control/crazyflie_control_rate.h"
#include "core/input_error.h"
#include "core/input_file.h"
#include "planning/grid/movingai.h"
#include "planning/worlds/grid_map_world.h"
#include "sim/scenario.h"
#include "sim/scenario_reference.h"
#include "sim/scenario_sensing.h"
#include "sim/yaml_document.h"
#include "sim/yaml_reader.h"

namespace cosim {

namespace {

constexpr double kMaxWorldExtent = 10000.0;  // m; larger worlds are surely a units mistake
// MuJoCo's compiler, its collision phase, the planners' worlds and the clearance metric all
// scale with the number of obstacles: 5 000 boxes took 4.4 s to compile here, 20 000 took 22 s
// (one 500 m world, a loaded 2-core machine). The bundled worlds have at most 300.
constexpr std::size_t kMaxObstacles = 10000;
constexpr std::size_t kMaxWaypoints = 100000;
constexpr std::size_t kMaxVehicleNameLength = 64;
// Point-in-obstacle tests the loader may make (checkPlacementWork): about 2 s here.
constexpr double kMaxPlacementChecks = 2e8;
// The flight log keeps one sample (about 250 bytes) per vehicle per control step, reserved up
// front: 20 million samples is about 5 GB. More is a mistake (a day at 10 kHz), refused before
// anything is allocated.
constexpr double kMaxLogSamples = 2e7;

void readObstacle(const YamlReader& r, const YAML::Node& n, const std::string& key, Obstacle& o) {
  r.requireMap(n, key);
  if (!n["type"]) r.fail(n, key, "obstacle needs a 'type' (box, cylinder or sphere)");
  const std::string type = r.text(n["type"], key + ".type");
  if (type == "box") {
    r.checkKeys(n, key, {"type", "pos", "size", "yaw"});
    o.type = ObstacleType::Box;
    if (!n["size"]) r.fail(n, key, "box needs 'size: [x, y, z]' (full edge lengths)");
    o.size = r.vec3(n["size"], key + ".size");
    if ((o.size.array() <= 0).any()) r.fail(n["size"], key + ".size", "sizes must be positive");
  } else if (type == "cylinder") {
    r.checkKeys(n, key, {"type", "pos", "radius", "height", "yaw"});
    o.type = ObstacleType::Cylinder;
    if (!n["radius"] || !n["height"]) r.fail(n, key, "cylinder needs 'radius' and 'height'");
    o.radius = r.number(n["radius"], key + ".radius", 1e-6, kMaxWorldExtent);
    o.height = r.number(n["height"], key + ".height", 1e-6, kMaxWorldExtent);
  } else if (type == "sphere") {
    r.checkKeys(n, key, {"type", "pos", "radius"});
    o.type = ObstacleType::Sphere;
    if (!n["radius"]) r.fail(n, key, "sphere needs 'radius'");
    o.radius = r.number(n["radius"], key + ".radius", 1e-6, kMaxWorldExtent);
  } else {
    r.fail(n["type"], key + ".type",
           "unknown obstacle type '" + type + "' (box, cylinder, sphere)");
  }
  if (!n["pos"]) r.fail(n, key, "obstacle needs 'pos: [x, y, z]' (its centre)");
  o.pos = r.vec3(n["pos"], key + ".pos");
  if (n["yaw"]) o.yaw_deg = r.number(n["yaw"], key + ".yaw", -3600, 3600);
}

// world.grid_map: {file: MAP.map, cell: 0.5, height: 0.5, ceiling: 3, blocked: [[x, y], ...]}
void readGridMap(const YamlReader& r, const YAML::Node& n, const std::filesystem::path& dir,
                 Scenario& s) {
  const std::string key = "world.grid_map";
  r.requireMap(n, key);
  r.checkKeys(n, key, {"file", "cell", "height", "ceiling", "blocked"});
  if (!n["file"]) r.fail(n, key, "missing 'file' (a MovingAI .map)");
  GridMapSpec& g = s.grid_map;
  const std::string file = r.text(n["file"], key + ".file");
  g.file = std::filesystem::path(file).is_absolute() ? std::filesystem::path(file) : dir / file;
  try {
    checkInputFile(g.file.string(), kMaxMapFileBytes, "MovingAI map");
  } catch (const InputError& e) {
    r.fail(n["file"], key + ".file", g.file.string() + ": " + e.problem());
  }
  if (n["cell"]) g.cell = r.number(n["cell"], key + ".cell", 0.01, 100.0);
  if (n["height"]) g.height = r.number(n["height"], key + ".height", 0.01, 100.0);
  if (n["ceiling"]) g.ceiling = r.number(n["ceiling"], key + ".ceiling", 0.02, 1000.0);
  if (g.ceiling <= g.height) r.fail(n, key, "ceiling must be above the blocks' height");
  const OccupancyGrid map = readMovingAIMap(g.file.string());
  if (map.nx() * g.cell > kMaxWorldExtent || map.ny() * g.cell > kMaxWorldExtent)
    r.fail(n, key, "the world is larger than 10 km on an axis");
  g.grid = OccupancyGrid(map.nx(), map.ny(), 1, g.cell);
  for (int y = 0; y < map.ny(); ++y)
    for (int x = 0; x < map.nx(); ++x) g.grid.setBlocked(x, y, 0, map.blocked(x, y));
  if (n["blocked"]) {
    const YAML::Node b = n["blocked"];
    if (!b.IsSequence()) r.fail(b, key + ".blocked", "must be a list of [x, y] cells");
    for (std::size_t i = 0; i < b.size(); ++i) {
      const std::string k = key + ".blocked[" + std::to_string(i) + "]";
      if (!b[i].IsSequence() || b[i].size() != 2) r.fail(b[i], k, "expected [x, y] (column, row)");
      const long x = r.integer(b[i][0], k, 0, map.nx() - 1);
      const long y = r.integer(b[i][1], k, 0, map.ny() - 1);
      g.grid.setBlocked(static_cast<int>(x), static_cast<int>(y), 0, true);
    }
  }
  try {
    s.world = worldFromGridMap(g.grid, g.height, g.ceiling);
  } catch (const InputError& e) {
    r.fail(n["file"], key + ".file", e.problem());
  }
}

// Values given with --set come from the command line, not from a line of the file (YAML
// parses each one as a document of its own, so its nodes say "line 1"): their errors are placed
// at the assignment, "--set planner.resolution=fast, key planner.resolution". The key stays in
// the place, where sweeps look for it.
bool keyIsUnder(const std::string& key, const std::string& path) {
  return key.compare(0, path.size(), path) == 0 &&
         (key.size() == path.size() || key[path.size()] == '.' || key[path.size()] == '[');
}

// The --set assignment behind `key`: the last one naming the key or a mapping above it (it
// replaced everything below), or, if the key has no line in the file (`created`), the one whose
// path made it. Empty if the file gave the key.
std::string overrideBehind(const std::vector<std::string>& overrides, const std::string& key,
                           bool created) {
  for (auto o = overrides.rbegin(); o != overrides.rend(); ++o) {
    const std::string path = o->substr(0, o->find('='));
    if (keyIsUnder(key, path) || (created && keyIsUnder(path, key))) return *o;
  }
  return "";
}

std::string overridePlace(const std::string& assignment, const std::string& key) {
  return "--set " + assignment + ", key " + key;
}

// `e` placed at the --set assignment behind its key, if there is one. YamlReader's places are
// "line N, key K", or "key K" for a node an assignment created (it has no position).
InputError placedAtOverride(const InputError& e, const std::string& file,
                            const std::vector<std::string>& overrides) {
  const std::string& place = e.place();
  if (e.file() != file || overrides.empty()) return e;
  std::size_t key_at = std::string::npos;
  const bool positioned = place.rfind("line ", 0) == 0;
  if (positioned && place.find(", key ") != std::string::npos)
    key_at = place.find(", key ") + 6;
  else if (place.rfind("key ", 0) == 0)
    key_at = 4;
  if (key_at == std::string::npos) return e;
  const std::string key = place.substr(key_at);
  const std::string assignment = overrideBehind(overrides, key, !positioned);
  return assignment.empty() ? e : InputError(file, overridePlace(assignment, key), e.problem());
}

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

void checkPointPlacement(const YamlReader& r, const YAML::Node& n, const std::string& key,
                         const Scenario& s, const Eigen::Vector3d& p) {
  if (!s.world.insideBounds(p)) r.fail(n, key, "point is outside the world bounds");
  for (std::size_t i = 0; i < s.world.obstacles.size(); ++i)
    if (s.world.obstacles[i].signedDistance(p) <= 0.0)
      r.fail(n, key,
             "point is inside obstacle " + std::to_string(i + 1) + " (world.obstacles[" +
                 std::to_string(i) + "])");
}

// Every point of the scenario (vehicles' starts, goals and waypoints, moving obstacles' paths)
// is checked against every obstacle. Both lists are long only together by mistake (or by an
// alias repeating a long path), and the product is what costs: refused before it is paid.
void checkPlacementWork(const YamlReader& r, const YAML::Node& root, const Scenario& s) {
  const auto length = [](const YAML::Node& n) {
    return n.IsDefined() && n.IsSequence() ? n.size() : std::size_t{0};
  };
  const auto member = [](const YAML::Node& n, const char* key) {
    return n.IsDefined() && n.IsMap() ? n[key] : YAML::Node();
  };
  double points = 0;
  const YAML::Node vehicles = member(root, "vehicles");
  for (std::size_t i = 0; i < length(vehicles); ++i)
    points += 2.0 + static_cast<double>(length(member(vehicles[i], "waypoints")));
  const YAML::Node moving = member(member(root, "world"), "moving_obstacles");
  for (std::size_t i = 0; i < length(moving); ++i)
    points += static_cast<double>(length(member(moving[i], "path")));
  const double checks = points * static_cast<double>(s.world.obstacles.size());
  if (checks > kMaxPlacementChecks)
    r.fail(root["world"], "world",
           std::to_string(static_cast<long long>(points)) + " points x " +
               std::to_string(s.world.obstacles.size()) + " obstacles = " +
               std::to_string(static_cast<long long>(checks)) + " placement checks, more than " +
               std::to_string(static_cast<long long>(kMaxPlacementChecks)) +
               ": use fewer waypoints or fewer obstacles");
}

// world.moving_obstacles[i]: {type: cylinder, radius, height, path: [[x, y], ...], speed, loop}
// or {type: box, size: [x, y, z], ...}. Path points must be inside the bounds and clear of the
// static obstacles.
void readMovingObstacle(const YamlReader& r, const YAML::Node& n, const std::string& key,
                        Scenario& s) {
  r.requireMap(n, key);
  if (!n["type"]) r.fail(n, key, "moving obstacle needs a 'type' (cylinder or box)");
  MovingObstacleSpec o;
  const std::string type = r.text(n["type"], key + ".type");
  if (type == "cylinder") {
    r.checkKeys(n, key, {"type", "radius", "height", "path", "speed", "loop"});
    if (!n["radius"]) r.fail(n, key, "cylinder needs 'radius'");
    o.radius = r.number(n["radius"], key + ".radius", 1e-3, kMaxWorldExtent);
  } else if (type == "box") {
    r.checkKeys(n, key, {"type", "size", "path", "speed", "loop"});
    o.type = ObstacleType::Box;
    if (!n["size"]) r.fail(n, key, "box needs 'size: [x, y, z]' (full edge lengths)");
    o.size = r.vec3(n["size"], key + ".size");
    if ((o.size.array() <= 0).any()) r.fail(n["size"], key + ".size", "sizes must be positive");
    o.height = o.size.z();
  } else {
    r.fail(n["type"], key + ".type", "moving obstacles are 'cylinder' or 'box'");
  }
  if (n["height"]) o.height = r.number(n["height"], key + ".height", 1e-3, kMaxWorldExtent);
  if (!n["path"] || !n["path"].IsSequence() || n["path"].size() == 0)
    r.fail(n, key, "moving obstacle needs 'path: [[x, y], ...]' (at least one point)");
  if (n["path"].size() > kMaxWaypoints) r.fail(n["path"], key + ".path", "too many points");
  for (std::size_t i = 0; i < n["path"].size(); ++i) {
    const YAML::Node p = n["path"][i];
    const std::string k = key + ".path[" + std::to_string(i) + "]";
    if (!p.IsSequence() || p.size() != 2) r.fail(p, k, "must be [x, y]");
    const Eigen::Vector2d xy(r.number(p[0], k + "[0]", -1e9, 1e9),
                             r.number(p[1], k + "[1]", -1e9, 1e9));
    checkPointPlacement(r, p, k, s,
                        Eigen::Vector3d(xy.x(), xy.y(), s.world.bounds_min.z() + 0.5 * o.height));
    o.path.push_back(xy);
  }
  if (n["speed"]) o.speed = r.number(n["speed"], key + ".speed", 0.0, 100.0);
  if (o.path.size() > 1 && !(o.speed > 0))
    r.fail(n, key, "a moving obstacle with a path needs 'speed' > 0 (m/s)");
  if (n["loop"]) o.loop = r.boolean(n["loop"], key + ".loop");
  s.moving_obstacles.push_back(std::move(o));
}

// Vehicle names: 1 to kMaxVehicleNameLength printable ASCII characters other than space and '/'
// (MuJoCo names are "<vehicle>/<part>"). Commas and quotes are fine (the CSV files quote them);
// line breaks and other control bytes would split a log's rows. "" if `name` is fine.
std::string vehicleNameProblem(const std::string& name) {
  if (name.size() > kMaxVehicleNameLength)
    return "a vehicle name has at most " + std::to_string(kMaxVehicleNameLength) +
           " characters (this one has " + std::to_string(name.size()) + ")";
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte <= 0x20 || byte >= 0x7f || c == '/')
      return "vehicle names are printable ASCII without spaces or '/' (this one has " +
             (byte < 0x20 || byte == 0x7f ? std::string("a control character")
              : byte >= 0x80              ? std::string("a non-ASCII character")
                                          : "'" + std::string(1, c) + "'") +
             ")";
  }
  return "";
}

void readVehicle(const YamlReader& r, const YAML::Node& n, const std::string& key,
                 const std::filesystem::path& scenario_dir, Scenario& s) {
  r.checkKeys(n, key, {"name", "model", "start", "goal", "waypoints", "yaw", "reference", "mass"});
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
  s.vehicles.push_back(std::move(v));
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
void readMotionSections(const YamlReader& r, const YAML::Node& parent, const std::string& prefix,
                        const std::vector<std::string>& overrides, Sections& out) {
  if (parent["planner"] && !parent["planner"].IsNull()) {
    const YAML::Node p = parent["planner"];
    r.requireMap(p, prefix + "planner");
    if (!p["name"]) r.fail(p, prefix + "planner", "missing 'name' (e.g. theta_star)");
    out.planner_name = r.text(p["name"], prefix + "planner.name");
    if (p["margin"]) out.planner_margin = r.number(p["margin"], prefix + "planner.margin", 0.0, 100.0);
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
    r.checkKeys(c, prefix + "controller", {"name", "gains", "drag_compensation"});
    out.controller_given = true;
    if (c["name"]) out.controller_name = r.text(c["name"], prefix + "controller.name");
    const std::string& name = out.controller_name;
    if (name != "cascade" && name != "geometric" && name != "indi" && name != "dsl_pid" &&
        name != "crazyflie_lee" && name != "crazyflie_mellinger" && name != "crazyflie_pid")
      r.fail(c["name"], prefix + "controller.name",
             "must be 'cascade', 'geometric', 'indi', 'dsl_pid', 'crazyflie_lee', "
             "'crazyflie_mellinger' or 'crazyflie_pid'");
    if (c["drag_compensation"]) {
      out.controller_drag_compensation =
          r.boolean(c["drag_compensation"], prefix + "controller.drag_compensation");
      if (out.controller_drag_compensation && name != "geometric" && name != "indi")
        r.fail(c["drag_compensation"], prefix + "controller.drag_compensation",
               "applies to the 'geometric' and 'indi' controllers, not '" + name + "'");
    }
    if (c["gains"]) readParams(r, c["gains"], prefix + "controller.gains", {}, overrides, out.controller_gains);
  }
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

Scenario loadScenario(const std::string& path, const std::vector<std::string>& overrides) {
  return parseScenario(readInputFile(path, kMaxScenarioFileBytes, "scenario file"), path,
                       overrides);
}

// parseScenario without placing errors at their --set assignments.
static Scenario parseScenarioText(const std::string& text, const std::string& file,
                                  const std::vector<std::string>& overrides) {
  const YamlReader r(file);
  YAML::Node root = loadYamlDocument(text, file);
  if (!root.IsDefined() || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  for (const auto& o : overrides) applyYamlOverride(root, o);
  r.checkKeys(root, "",
              {"world", "vehicles", "planner", "trajectory", "controller", "aerial", "sim",
               "disturbances", "sensors", "estimator", "model_error", "render"});

  Scenario s;
  s.file = file;
  s.effective_yaml = YAML::Dump(root) + "\n";
  const std::filesystem::path dir = std::filesystem::path(file).parent_path();
  s.planner_params = ParamSet(file);
  s.trajectory_params = ParamSet(file);
  s.controller_gains = ParamSet(file);
  s.aerial.planner_params = ParamSet(file);
  s.aerial.trajectory_params = ParamSet(file);
  s.aerial.controller_gains = ParamSet(file);

  // world
  if (!root["world"]) r.fail(root, "world", "missing 'world' section");
  const YAML::Node world = root["world"];
  r.checkKeys(world, "world", {"bounds", "obstacles", "include", "moving_obstacles", "grid_map"});
  if (world["grid_map"]) {
    readGridMap(r, world["grid_map"], dir, s);
    for (const char* key : {"bounds", "obstacles"})
      if (world[key])
        r.fail(world[key], std::string("world.") + key,
               "comes from world.grid_map (add obstacle cells with grid_map.blocked)");
  } else {
    if (!world["bounds"]) r.fail(world, "world", "missing 'bounds: {min: [..], max: [..]}'");
    r.checkKeys(world["bounds"], "world.bounds", {"min", "max"});
    if (!world["bounds"]["min"] || !world["bounds"]["max"])
      r.fail(world["bounds"], "world.bounds", "needs both 'min' and 'max'");
    s.world.bounds_min = r.vec3(world["bounds"]["min"], "world.bounds.min");
    s.world.bounds_max = r.vec3(world["bounds"]["max"], "world.bounds.max");
    const Eigen::Vector3d extent = s.world.bounds_max - s.world.bounds_min;
    if ((extent.array() <= 0).any())
      r.fail(world["bounds"], "world.bounds", "max must exceed min on every axis");
    if ((extent.array() > kMaxWorldExtent).any())
      r.fail(world["bounds"], "world.bounds", "the world is larger than 10 km on an axis");
    if (world["obstacles"]) {
      const YAML::Node obs = world["obstacles"];
      if (!obs.IsSequence()) r.fail(obs, "world.obstacles", "must be a list");
      if (obs.size() > kMaxObstacles)
        r.fail(obs, "world.obstacles", "more than " + std::to_string(kMaxObstacles) + " obstacles");
      for (std::size_t i = 0; i < obs.size(); ++i) {
        Obstacle o;
        readObstacle(r, obs[i], "world.obstacles[" + std::to_string(i) + "]", o);
        s.world.obstacles.push_back(o);
      }
    }
  }
  checkPlacementWork(r, root, s);
  if (world["moving_obstacles"]) {
    const YAML::Node mo = world["moving_obstacles"];
    if (!mo.IsSequence()) r.fail(mo, "world.moving_obstacles", "must be a list");
    if (mo.size() > 1000) r.fail(mo, "world.moving_obstacles", "more than 1000 moving obstacles");
    for (std::size_t i = 0; i < mo.size(); ++i)
      readMovingObstacle(r, mo[i], "world.moving_obstacles[" + std::to_string(i) + "]", s);
  }
  if (world["include"]) {
    const std::string inc = r.text(world["include"], "world.include");
    s.include_file =
        std::filesystem::path(inc).is_absolute() ? std::filesystem::path(inc) : dir / inc;
    try {
      checkInputFile(s.include_file.string(), kMaxModelFileBytes, "MJCF fragment");
    } catch (const InputError& e) {
      r.fail(world["include"], "world.include", s.include_file.string() + ": " + e.problem());
    }
  }

  // vehicles
  if (!root["vehicles"]) r.fail(root, "vehicles", "missing 'vehicles' list");
  const YAML::Node vehicles = root["vehicles"];
  if (!vehicles.IsSequence() || vehicles.size() == 0)
    r.fail(vehicles, "vehicles", "must be a non-empty list");
  if (vehicles.size() > 1000) r.fail(vehicles, "vehicles", "more than 1000 vehicles");
  for (std::size_t i = 0; i < vehicles.size(); ++i)
    readVehicle(r, vehicles[i], "vehicles[" + std::to_string(i) + "]", dir, s);

  readMotionSections(r, root, "", overrides, s);
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
    readMotionSections(r, n, "aerial.", overrides, s.aerial);
  }

  // sim
  if (root["sim"]) {
    const YAML::Node n = root["sim"];
    r.checkKeys(n, "sim", {"timestep", "control_rate", "max_time", "seed", "goal_tolerance"});
    if (n["timestep"]) s.sim.timestep = r.number(n["timestep"], "sim.timestep", 1e-5, 0.02);
    if (n["control_rate"])
      s.sim.control_rate = r.number(n["control_rate"], "sim.control_rate", 1.0, 10000.0);
    if (n["max_time"]) s.sim.max_time = r.number(n["max_time"], "sim.max_time", 0.01, 86400.0);
    if (n["seed"])
      s.sim.seed = static_cast<std::uint64_t>(r.integer(n["seed"], "sim.seed", 0, 2147483647L));
    if (n["goal_tolerance"])
      s.sim.goal_tolerance = r.number(n["goal_tolerance"], "sim.goal_tolerance", 0.01, 100.0);
    const double ratio = 1.0 / (s.sim.timestep * s.sim.control_rate);
    if (ratio < 1.0 - 1e-9 || std::abs(ratio - std::round(ratio)) > 1e-6)
      r.fail(n["control_rate"] ? n["control_rate"] : n, "sim.control_rate",
             "the physics rate (1/timestep) must be a whole multiple of the control rate");
  }
  for (const std::string& name : {s.controller_name, s.aerial.controller_name})
    if (const std::string why = crazyflieControlRateProblem(name, s.sim.control_rate); !why.empty())
      r.fail(root["sim"] && root["sim"]["control_rate"] ? root["sim"]["control_rate"] : root,
             "sim.control_rate", why);
  if (const double samples =
          s.sim.max_time * s.sim.control_rate * static_cast<double>(s.vehicles.size());
      samples > kMaxLogSamples)
    r.fail(
        root["sim"] ? root["sim"] : root, "sim.max_time",
        "max_time x control_rate x vehicles = " + std::to_string(static_cast<long long>(samples)) +
            " log samples, more than 20 million: shorten sim.max_time or lower sim.control_rate");
  checkReferenceStarts(r, root, s);

  // disturbances
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
      r.fail(n["wind"] ? n["wind"] : n["gust"], n["wind"] ? "disturbances.wind" : "disturbances.gust",
             "wind acts through drag and this scenario has none: add rotor_drag: true (the "
             "airframe's per-rotor drag) or drag: K (N per m/s)");
  }

  readSensingSections(r, root, s);

  // render
  if (root["render"]) {
    const YAML::Node n = root["render"];
    r.checkKeys(n, "render",
                {"camera", "cameras", "width", "height", "fps", "speed", "speedup", "fixed_camera",
                 "obstacle_alpha", "png_frames", "team_plans"});
    const auto readCamera = [&](const YAML::Node& c, const std::string& key) {
      const std::string name = r.text(c, key);
      try {
        return cameraKind(name);
      } catch (const std::invalid_argument&) {
        r.fail(c, key, std::string("must be ") + cameraNames());
      }
    };
    if (n["camera"]) s.render.camera = readCamera(n["camera"], "render.camera");
    if (n["cameras"]) {
      if (!n["cameras"].IsSequence())
        r.fail(n["cameras"], "render.cameras", "must be a list of camera names");
      for (std::size_t i = 0; i < n["cameras"].size(); ++i)
        s.render.cameras.push_back(
            readCamera(n["cameras"][i], "render.cameras[" + std::to_string(i) + "]"));
    }
    if (n["fixed_camera"]) {
      const YAML::Node f = n["fixed_camera"];
      r.checkKeys(f, "render.fixed_camera", {"pos", "lookat"});
      if (!f["pos"] || !f["lookat"]) r.fail(f, "render.fixed_camera", "needs 'pos' and 'lookat'");
      s.render.fixed_pos = r.vec3(f["pos"], "render.fixed_camera.pos");
      s.render.fixed_lookat = r.vec3(f["lookat"], "render.fixed_camera.lookat");
      if ((s.render.fixed_pos - s.render.fixed_lookat).norm() < 1e-6)
        r.fail(f, "render.fixed_camera", "pos and lookat must differ");
      s.render.has_fixed_camera = true;
    }
    bool wants_fixed = s.render.camera == CameraKind::Fixed;
    for (const auto& c : s.render.cameras) wants_fixed = wants_fixed || c == CameraKind::Fixed;
    if (wants_fixed && !s.render.has_fixed_camera)
      r.fail(n, "render",
             "camera 'fixed' needs render.fixed_camera: {pos: [x, y, z], lookat: [x, y, z]}");
    // render.speed: the time-lapse factor; speedup is its older name (speed wins, so
    // --video-speed and --set render.speed=X apply to files that still say speedup).
    for (const char* key : {"speedup", "speed"})
      if (n[key])
        s.render.speedup = r.number(n[key], std::string("render.") + key, 0.01, 1000.0);
    if (n["obstacle_alpha"])
      s.render.obstacle_alpha = r.number(n["obstacle_alpha"], "render.obstacle_alpha", 0.05, 1.0);
    if (n["png_frames"]) s.render.png_frames = r.boolean(n["png_frames"], "render.png_frames");
    if (n["team_plans"]) s.render.team_plans = r.boolean(n["team_plans"], "render.team_plans");
    if (n["width"])
      s.render.width = static_cast<int>(r.integer(n["width"], "render.width", 64, 3840));
    if (n["height"])
      s.render.height = static_cast<int>(r.integer(n["height"], "render.height", 64, 2160));
    if (n["fps"]) s.render.fps = static_cast<int>(r.integer(n["fps"], "render.fps", 1, 240));
    // H.264 with yuv420p needs even frame sizes.
    if (s.render.width % 2 || s.render.height % 2)
      r.fail(n, "render", "width and height must be even (H.264, yuv420p)");
  }
  return s;
}

Scenario parseScenario(const std::string& text, const std::string& file,
                       const std::vector<std::string>& overrides) {
  try {
    return parseScenarioText(text, file, overrides);
  } catch (const InputError& e) {
    throw placedAtOverride(e, file, overrides);
  }
}

}  // namespace cosim
