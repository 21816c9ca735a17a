// Reading a scenario's `world:` section (part of sim/scenario_loader.cpp): the static obstacles
// the planners see, the moving ones they do not, and a fragment of MJCF the physics adds.
#include <string>

#include "core/input_error.h"
#include "core/input_file.h"
#include "planning/grid/movingai.h"
#include "planning/world/grid_map_world.h"
#include "sim/declared_key_reader.h"
#include "sim/scenario_sections.h"

namespace cosim {

namespace {

// MuJoCo's compiler, its collision phase, the planners' worlds and the clearance metric all
// scale with the number of obstacles: 5 000 boxes took 4.4 s to compile here, 20 000 took 22 s
// (one 500 m world, a loaded 2-core machine). The bundled worlds have at most 300.
constexpr std::size_t kMaxObstacles = 10000;
// Point-in-obstacle tests the loader may make (checkPlacementWork): about 2 s here.
constexpr double kMaxPlacementChecks = 2e8;

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
  GridMapSpec& g = s.grid_map;
  r.checkKeys(n, key, declaredKeyNames(g));
  if (!n["file"]) r.fail(n, key, "missing 'file' (a MovingAI .map)");
  const std::string file = r.text(n["file"], key + ".file");
  g.file = std::filesystem::path(file).is_absolute() ? std::filesystem::path(file) : dir / file;
  try {
    checkInputFile(g.file.string(), kMaxMapFileBytes, "MovingAI map");
  } catch (const InputError& e) {
    r.fail(n["file"], key + ".file", g.file.string() + ": " + e.problem());
  }
  DeclaredKeyReader declared(r, n, key);
  g.declareKeys(declared);
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

// world.bounds: {min: [x, y, z], max: [x, y, z]} and world.obstacles: [...], for a world
// without a grid map.
void readBoundsAndObstacles(const YamlReader& r, const YAML::Node& world, Scenario& s) {
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

}  // namespace

void checkPointPlacement(const YamlReader& r, const YAML::Node& n, const std::string& key,
                         const Scenario& s, const Eigen::Vector3d& p) {
  if (!s.world.insideBounds(p)) r.fail(n, key, "point is outside the world bounds");
  for (std::size_t i = 0; i < s.world.obstacles.size(); ++i)
    if (s.world.obstacles[i].signedDistance(p) <= 0.0)
      r.fail(n, key,
             "point is inside world.obstacles[" + std::to_string(i) +
                 "] (obstacles are numbered from 0 in the file's order, as --set numbers them)");
}

void readWorldSection(const YamlReader& r, const YAML::Node& root, const std::filesystem::path& dir,
                      Scenario& s) {
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
    readBoundsAndObstacles(r, world, s);
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
}

}  // namespace cosim
