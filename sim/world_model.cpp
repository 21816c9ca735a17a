#include "sim/world_model.h"

#include <tinyxml2.h>

#include <cmath>
#include <cstring>
#include <sstream>
#include <utility>

#include "core/decimal_text.h"
#include "core/input_error.h"
#include "core/input_file.h"
#include "sim/ground_vehicle_handles.h"
#include "sim/moving_obstacle_motion.h"
#include "sim/mujoco_messages.h"
#include "sim/quadrotor_vehicle_handles.h"
#include "sim/urdf_vehicle.h"
#include "sim/world_fragment.h"

namespace cosim {

namespace {

using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;
using tinyxml2::XMLNode;

std::string vectorText(const Eigen::Vector3d& v) {
  return tenSignificantDigits(v.x()) + " " + tenSignificantDigits(v.y()) + " " +
         tenSignificantDigits(v.z());
}

// Attributes that name something (prefixed) or refer to a named thing (prefixed the same way).
const char* const kNameAttributes[] = {
    "name",  "class",  "childclass", "site",    "joint",    "body", "body1",   "body2",  "geom1",
    "geom2", "tendon", "objname",    "refsite", "material", "mesh", "texture", "hfield", "target"};

void prefixNames(XMLElement* e, const std::string& prefix) {
  for (const char* attr : kNameAttributes)
    if (const char* v = e->Attribute(attr)) e->SetAttribute(attr, (prefix + v).c_str());
  for (XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement())
    prefixNames(c, prefix);
}

XMLElement* add(XMLDocument& doc, XMLNode* parent, const char* tag) {
  XMLElement* e = doc.NewElement(tag);
  parent->InsertEndChild(e);
  return e;
}

void addObstacleGeom(XMLDocument& doc, XMLElement* worldbody, const Obstacle& o, std::size_t i) {
  XMLElement* g = add(doc, worldbody, "geom");
  g->SetAttribute("name", ("obstacle" + std::to_string(i)).c_str());
  g->SetAttribute("pos", vectorText(o.pos).c_str());
  g->SetAttribute("material", "obstacle");
  switch (o.type) {
    case ObstacleType::Box:
      g->SetAttribute("type", "box");
      g->SetAttribute("size", vectorText(0.5 * o.size).c_str());
      g->SetAttribute("euler", ("0 0 " + tenSignificantDigits(o.yaw_deg)).c_str());
      break;
    case ObstacleType::Cylinder:
      g->SetAttribute("type", "cylinder");
      g->SetAttribute(
          "size",
          (tenSignificantDigits(o.radius) + " " + tenSignificantDigits(0.5 * o.height)).c_str());
      break;
    case ObstacleType::Sphere:
      g->SetAttribute("type", "sphere");
      g->SetAttribute("size", tenSignificantDigits(o.radius).c_str());
      break;
  }
}

// vehicles[i].mass: the base's <inertial> gets the flown total mass, and its principal inertia
// the same ratio. Scaling at constant radii of gyration is the first-order guess for mass added
// over the airframe's own footprint (a battery under the centre, decks on top, markers on the
// arms); keeping the inertia would treat every added gram as a point at the centre.
void setTotalMass(XMLElement* base, const VehicleSpec& v) {
  XMLElement* inertial = base->FirstChildElement("inertial");
  double mass = 0.0;
  if (!inertial || inertial->QueryDoubleAttribute("mass", &mass) != tinyxml2::XML_SUCCESS ||
      !(mass > 0.0) || base->FirstChildElement("body"))
    throw InputError(v.model_file.string(), "<body name=\"base\">",
                     "vehicle '" + v.name +
                         "' sets mass: the model needs one base body with an "
                         "<inertial mass=...> and no child bodies");
  const double ratio = v.mass / mass;
  inertial->SetAttribute("mass", tenSignificantDigits(v.mass).c_str());
  if (const char* d = inertial->Attribute("diaginertia")) {
    std::istringstream in(d);
    Eigen::Vector3d j;
    if (!(in >> j.x() >> j.y() >> j.z()))
      throw InputError(v.model_file.string(), "<inertial diaginertia>", "needs three numbers");
    inertial->SetAttribute("diaginertia", vectorText(ratio * j).c_str());
  } else if (inertial->Attribute("fullinertia")) {
    throw InputError(v.model_file.string(), "<inertial>",
                     "vehicle '" + v.name + "' sets mass: use diaginertia, not fullinertia");
  }
}

void addVehicle(XMLDocument& doc, XMLElement* worldbody, XMLElement* custom, const VehicleSpec& v) {
  const std::string text = readInputFile(v.model_file.string(), kMaxModelFileBytes, "model file");
  XMLDocument src;
  if (src.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
    throw InputError(v.model_file.string(), "line " + std::to_string(src.ErrorLineNum()),
                     std::string("cannot parse model XML: ") + src.ErrorName());
  XMLElement* root = src.FirstChildElement("mujoco");
  if (!root) throw InputError(v.model_file.string(), "", "no <mujoco> root element");
  XMLElement* wb = root->FirstChildElement("worldbody");
  XMLElement* body = wb ? wb->FirstChildElement("body") : nullptr;
  if (!body || !body->Attribute("name", "base"))
    throw InputError(v.model_file.string(), "<worldbody>", "expected one <body name=\"base\">");
  const std::string prefix = v.name + "/";

  XMLElement* copy = body->DeepClone(&doc)->ToElement();
  prefixNames(copy, prefix);
  // The start pose is the body's own pose, so qpos0 (and a reset) puts the vehicle at its start.
  copy->SetAttribute("pos", vectorText(v.start).c_str());
  copy->SetAttribute("euler", ("0 0 " + tenSignificantDigits(v.yaw_deg)).c_str());
  if (v.mass > 0.0) setTotalMass(copy, v);
  worldbody->InsertEndChild(copy);

  // The rotor constants of <custom> (sim/ reads them as "<name>/thrust_coefficient" and so on),
  // prefixed like the body. The rotors' thrust is sim/'s to apply: an actuator would double it.
  if (root->FirstChildElement("actuator"))
    throw InputError(v.model_file.string(), "<actuator>",
                     "a quadrotor model has no actuators: sim/ applies the rotors' thrust and "
                     "reaction torques from the <custom> rotor constants");
  XMLElement* from = root->FirstChildElement("custom");
  for (XMLElement* a = from ? from->FirstChildElement() : nullptr; a; a = a->NextSiblingElement()) {
    XMLElement* ac = a->DeepClone(&doc)->ToElement();
    prefixNames(ac, prefix);
    custom->InsertEndChild(ac);
  }
}

// MuJoCo's message on one line (it separates its parts with line breaks).
std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

// The composed world did not compile: whose fault? A world fragment that does not compile on its
// own is reported against the fragment (MuJoCo's lines are then the fragment's lines); one that
// does, against the scenario's world.include (it clashes with the rest, e.g. a repeated name);
// anything else against the scenario.
InputError compileError(const Scenario& scenario, const std::string& error) {
  if (!scenario.include_file.empty()) {
    char alone_error[1024] = "";
    // MuJoCo resolves the fragment's relative file names against its folder itself here.
    mjModel* alone =
        mj_loadXML(scenario.include_file.c_str(), nullptr, alone_error, sizeof alone_error);
    if (!alone)
      return InputError(
          scenario.include_file.string(), "",
          "MuJoCo cannot compile this world fragment (world.include): " + oneLine(alone_error));
    mj_deleteModel(alone);
    return InputError(scenario.file, "key world.include",
                      "the fragment " + scenario.include_file.string() +
                          " does not fit the composed world: " + oneLine(error));
  }
  return InputError(scenario.file, "world",
                    "MuJoCo cannot compile the composed world: " + oneLine(error));
}

// Rendering settings: the off-screen buffer, the lens, the level of detail and the headlight.
void addVisual(XMLDocument& doc, XMLElement* mujoco, const Scenario& s) {
  const double extent = (s.world.bounds_max - s.world.bounds_min).norm();
  XMLElement* visual = add(doc, mujoco, "visual");
  XMLElement* global = add(doc, visual, "global");
  // The off-screen buffer size comes from the model; without this, frames are cut to 640x480.
  global->SetAttribute("offwidth", s.render.width);
  global->SetAttribute("offheight", s.render.height);
  global->SetAttribute("fovy", 45);
  XMLElement* quality = add(doc, visual, "quality");
  // Software rendering (OSMesa) pays for every pixel of a shadow map and every multisample:
  // a 4096 shadow map and 4x MSAA made a 1280x720 frame cost about 0.8 s of CPU here. Shadows
  // stay (they show height above the floor) with a smaller map; no multisampling. Curved
  // surfaces get 16 slices and 8 stacks instead of MuJoCo's 28 and 16: the hundreds of capsules
  // that draw the paths and the trail were most of a frame's triangles (measured here: 12.3 ->
  // 16.2 frames/s for a full 1280x720 frame, and the faceting does not show at that size).
  quality->SetAttribute("shadowsize", 1024);
  quality->SetAttribute("offsamples", 0);
  quality->SetAttribute("numslices", 16);
  quality->SetAttribute("numstacks", 8);
  XMLElement* map = add(doc, visual, "map");
  map->SetAttribute("znear", tenSignificantDigits(0.05 / std::max(extent, 1.0)).c_str());
  map->SetAttribute("zfar", "10");
  XMLElement* headlight = add(doc, visual, "headlight");
  headlight->SetAttribute("ambient", "0.35 0.35 0.35");
  headlight->SetAttribute("diffuse", "0.5 0.5 0.5");
}

// The sky, the floor's checker texture and the materials of the floor and the obstacles.
void addAssets(XMLDocument& doc, XMLElement* mujoco, const Scenario& s) {
  const Eigen::Vector3d lo = s.world.bounds_min, hi = s.world.bounds_max;
  XMLElement* asset = add(doc, mujoco, "asset");
  XMLElement* sky = add(doc, asset, "texture");
  sky->SetAttribute("name", "sky");
  sky->SetAttribute("type", "skybox");
  sky->SetAttribute("builtin", "gradient");
  sky->SetAttribute("rgb1", "0.55 0.7 0.9");
  sky->SetAttribute("rgb2", "0.95 0.97 1.0");
  sky->SetAttribute("width", 256);
  sky->SetAttribute("height", 256);
  XMLElement* grid = add(doc, asset, "texture");
  grid->SetAttribute("name", "grid");
  grid->SetAttribute("type", "2d");
  grid->SetAttribute("builtin", "checker");
  // Lit head-on by the headlight (0.35 ambient + 0.5 diffuse) and the sun (0.6), a surface
  // receives up to 1.45 times its colour: 0.82 came out pure white in the overview and top
  // views, one square in two. At most 0.64 x 1.45 = 0.93 keeps both squares apart; no
  // specular highlight (MuJoCo's default 0.5) washes them out either.
  grid->SetAttribute("rgb1", "0.64 0.66 0.68");
  grid->SetAttribute("rgb2", "0.56 0.58 0.60");
  grid->SetAttribute("width", 512);
  grid->SetAttribute("height", 512);
  XMLElement* floor_mat = add(doc, asset, "material");
  floor_mat->SetAttribute("name", "floor");
  floor_mat->SetAttribute("texture", "grid");
  floor_mat->SetAttribute("specular", "0");
  // One checker square per 2 m of world.
  floor_mat->SetAttribute("texrepeat", (tenSignificantDigits((hi.x() - lo.x()) / 4.0) + " " +
                                        tenSignificantDigits((hi.y() - lo.y()) / 4.0))
                                           .c_str());
  XMLElement* obstacle_mat = add(doc, asset, "material");
  obstacle_mat->SetAttribute("name", "obstacle");
  obstacle_mat->SetAttribute("rgba", "0.55 0.6 0.68 1");
  obstacle_mat->SetAttribute("specular", "0.2");
}

// The worldbody with what does not move: the sun, the floor, the obstacles and the scenario's
// MJCF fragment.
XMLElement* addStaticWorld(XMLDocument& doc, XMLElement* mujoco, const Scenario& s) {
  const Eigen::Vector3d lo = s.world.bounds_min, hi = s.world.bounds_max;
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const double extent = (hi - lo).norm();
  XMLElement* worldbody = add(doc, mujoco, "worldbody");
  XMLElement* light = add(doc, worldbody, "light");
  light->SetAttribute("directional", "true");
  light->SetAttribute("pos",
                      vectorText(Eigen::Vector3d(centre.x(), centre.y(), hi.z() + extent)).c_str());
  light->SetAttribute("dir", "-0.3 -0.4 -1");
  light->SetAttribute("diffuse", "0.6 0.6 0.6");
  light->SetAttribute("castshadow", "true");
  XMLElement* floor = add(doc, worldbody, "geom");
  floor->SetAttribute("name", "floor");
  floor->SetAttribute("type", "plane");
  floor->SetAttribute("pos", vectorText(Eigen::Vector3d(centre.x(), centre.y(), lo.z())).c_str());
  floor->SetAttribute("size", (tenSignificantDigits(0.5 * (hi.x() - lo.x())) + " " +
                               tenSignificantDigits(0.5 * (hi.y() - lo.y())) + " 0.1")
                                  .c_str());
  floor->SetAttribute("material", "floor");
  for (std::size_t i = 0; i < s.world.obstacles.size(); ++i)
    addObstacleGeom(doc, worldbody, s.world.obstacles[i], i);
  if (!s.include_file.empty()) addWorldFragment(doc, mujoco, s.include_file);
  return worldbody;
}

// The vehicles (their rotor constants in <custom>), the contact buffers they need (<size>, after
// <option>) and the moving obstacles.
void addVehicles(XMLDocument& doc, XMLElement* mujoco, XMLElement* option, XMLElement* worldbody,
                 const Scenario& s) {
  const Eigen::Vector3d lo = s.world.bounds_min;
  XMLElement* custom = doc.NewElement("custom");
  int on_floor = 0;  // robots whose wheels touch the floor at every step
  for (const VehicleSpec& v : s.vehicles) {
    if (v.kind == VehicleKind::GroundRobot)
      on_floor += addUrdfVehicle(doc, worldbody, v, lo.z()) ? 1 : 0;
    else
      addVehicle(doc, worldbody, custom, v);
  }
  // MuJoCo 2.2.2 preallocates its contact and constraint buffers (100 contacts, 500 rows by
  // default) and its constraint Jacobian as njmax x nv: size them to what can touch at once, a
  // robot on wheels making about 3 contacts of 4 pyramidal rows each, plus room for collisions.
  XMLElement* size = doc.NewElement("size");
  size->SetAttribute("nconmax", 100 + 4 * on_floor);
  size->SetAttribute("njmax", 500 + 16 * on_floor);
  mujoco->InsertAfterChild(option, size);
  addMovingObstacleBodies(doc, worldbody, s);
  if (custom->FirstChildElement()) mujoco->InsertEndChild(custom);
}

}  // namespace

std::string composeWorldXml(const Scenario& s) {
  XMLDocument doc;
  XMLElement* mujoco = add(doc, &doc, "mujoco");
  mujoco->SetAttribute("model", "cosim");
  XMLElement* compiler = add(doc, mujoco, "compiler");
  compiler->SetAttribute("autolimits", "true");  // MuJoCo 2.2.2 needs it for ctrlrange
  compiler->SetAttribute("angle", "degree");
  XMLElement* option = add(doc, mujoco, "option");
  option->SetAttribute("timestep", tenSignificantDigits(s.sim.timestep).c_str());
  option->SetAttribute("gravity", "0 0 -9.81");
  addVisual(doc, mujoco, s);
  addAssets(doc, mujoco, s);
  XMLElement* worldbody = addStaticWorld(doc, mujoco, s);
  addVehicles(doc, mujoco, option, worldbody, s);

  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

WorldModel WorldModel::build(const Scenario& scenario) {
  return fromXml(composeWorldXml(scenario), scenario);
}

WorldModel WorldModel::fromXml(const std::string& xml, const Scenario& scenario) {
  installMujocoMessageHandlers();  // before MuJoCo's first call: no MUJOCO_LOG.TXT, no exit(1)
  WorldModel wm;
  wm.xml_ = xml;
  // Load from memory through MuJoCo's virtual file system.
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  const char* name = "cosim_world.xml";
  if (mj_makeEmptyFileVFS(&vfs, name, static_cast<int>(xml.size())) != 0)
    throw std::runtime_error("MuJoCo VFS is full");
  const int index = mj_findFileVFS(&vfs, name);
  std::memcpy(vfs.filedata[index], xml.data(), xml.size());
  char error[1024] = "";
  mjModel* m = mj_loadXML(name, &vfs, error, sizeof error);
  mj_deleteVFS(&vfs);
  if (!m) throw compileError(scenario, error);
  wm.model_.reset(m);
  wm.floor_geom_ = mj_name2id(m, mjOBJ_GEOM, "floor");

  for (const VehicleSpec& v : scenario.vehicles) {
    VehicleHandles h;
    h.name = v.name;
    h.body = mj_name2id(m, mjOBJ_BODY, (v.name + "/base").c_str());
    if (v.kind == VehicleKind::GroundRobot)
      readGroundVehicleHandles(m, v, h);
    else
      readQuadrotorHandles(m, v, h);
    if (v.motor_speed_map) h.params.motor_speed_map = *v.motor_speed_map;
    if (v.battery && !h.params.hasMotorSpeedMap())
      throw InputError(scenario.file, "key vehicles[" + std::to_string(wm.vehicles_.size()) + "]",
                       "battery: model '" + v.model +
                           "' has no motor_speed_map (give vehicles[i].motor_speed_map: "
                           "[c0, c1, c2])");
    wm.vehicles_.push_back(std::move(h));
  }
  return wm;
}

}  // namespace cosim
