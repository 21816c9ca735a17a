#include "sim/urdf_vehicle.h"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/input_error.h"
#include "core/input_file.h"

namespace cosim {

namespace {

using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

// The drive's velocity servos settle like a first-order lag of this time constant (about 0.15 s
// to 95 %), typical of a small robot's motor-driver speed loop; design value. A servo's gain is
// the driven inertia divided by it, so every robot responds alike whatever its size.
constexpr double kDriveTimeConstant = 0.05;

// A ground robot's size limits (design values, far above real robots: a mobile manipulator has
// about 30 links, 10 deep). The depth also stays below the 100 levels of XML that tinyxml2, the
// parser MuJoCo reads the composed world with, accepts.
constexpr std::size_t kMaxUrdfLinks = 1000;
constexpr std::size_t kMaxUrdfDepth = 64;

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}
std::string fmt3(double a, double b, double c) {
  return fmt(a) + " " + fmt(b) + " " + fmt(c);
}

XMLElement* add(XMLDocument& doc, XMLElement* parent, const char* tag) {
  XMLElement* e = doc.NewElement(tag);
  parent->InsertEndChild(e);
  return e;
}

XMLElement* section(XMLDocument& doc, const char* tag) {
  XMLElement* root = doc.FirstChildElement("mujoco");
  XMLElement* e = root->FirstChildElement(tag);
  return e ? e : add(doc, root, tag);
}

Eigen::Vector3d vec(const urdf::Vector3& v) {
  return {v.x, v.y, v.z};
}
Eigen::Quaterniond quat(const urdf::Rotation& r) {
  return Eigen::Quaterniond(r.w, r.x, r.y, r.z);
}
Eigen::Isometry3d pose(const urdf::Pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = quat(p.rotation).normalized().toRotationMatrix();
  t.translation() = vec(p.position);
  return t;
}
void setPose(XMLElement* e, const urdf::Pose& p) {
  e->SetAttribute("pos", fmt3(p.position.x, p.position.y, p.position.z).c_str());
  const Eigen::Quaterniond q = quat(p.rotation).normalized();
  e->SetAttribute("quat", (fmt(q.w()) + " " + fmt3(q.x(), q.y(), q.z())).c_str());
}

// Collects urdfdom's console messages during a parse, so that its complaint becomes the text of
// one InputError instead of lines on stderr.
class ParseMessages : public console_bridge::OutputHandler {
 public:
  ParseMessages() { console_bridge::useOutputHandler(this); }
  ~ParseMessages() override { console_bridge::restorePreviousOutputHandler(); }
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first_error.empty())
      first_error = text;
  }
  std::string first_error;
};

// The joints must make a tree: urdfdom links each child to its parent with shared pointers, so a
// loop of joints (a -> b -> a) leaves a cycle of them behind when it then rejects the robot (a
// leak the fuzzer found). Checked here on the XML, iteratively (no recursion the input controls).
void checkJointGraph(const XMLDocument& xml, const std::string& file) {
  const XMLElement* robot = xml.FirstChildElement("robot");
  if (!robot) return;  // urdfdom names that problem
  std::map<std::string, std::string> parent_of;  // child link -> parent link
  for (const XMLElement* j = robot->FirstChildElement("joint"); j;
       j = j->NextSiblingElement("joint")) {
    const XMLElement* parent = j->FirstChildElement("parent");
    const XMLElement* child = j->FirstChildElement("child");
    const char* p = parent ? parent->Attribute("link") : nullptr;
    const char* c = child ? child->Attribute("link") : nullptr;
    if (!p || !c) continue;  // urdfdom names that problem
    const std::string where = "line " + std::to_string(j->GetLineNum()) + ", <joint>";
    if (!parent_of.emplace(c, p).second)
      throw InputError(file, where,
                       std::string("link '") + c + "' is the child of two joints (a kinematic "
                                                   "loop; a URDF robot is a tree)");
    // Walk up from the new joint's parent: reaching its child closes a loop. The walk ends within
    // the number of joints, since every earlier joint kept the graph a forest.
    for (auto it = parent_of.find(p); it != parent_of.end(); it = parent_of.find(it->second))
      if (it->first == c || it->second == c)
        throw InputError(file, where,
                         std::string("link '") + c + "' is its own ancestor (the joints form a "
                                                     "loop; a URDF robot is a tree)");
  }
}

urdf::ModelInterfaceSharedPtr parseUrdf(const std::string& file) {
  const std::string text = readInputFile(file, kMaxModelFileBytes, "URDF file");
  // tinyxml2 first: it reports XML syntax errors with a line number, urdfdom does not.
  XMLDocument xml;
  if (xml.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
    throw InputError(file, "line " + std::to_string(xml.ErrorLineNum()),
                     std::string("malformed XML: ") + xml.ErrorName());
  // Counted before urdfdom builds anything: a robot of thousands of links is a mistake that would
  // cost seconds and gigabytes in urdfdom and MuJoCo's compiler.
  if (const XMLElement* robot = xml.FirstChildElement("robot")) {
    std::size_t links = 0;
    for (const XMLElement* l = robot->FirstChildElement("link"); l;
         l = l->NextSiblingElement("link"))
      if (++links > kMaxUrdfLinks)
        throw InputError(file, "line " + std::to_string(l->GetLineNum()) + ", <link>",
                         "more than " + std::to_string(kMaxUrdfLinks) +
                             " links (a ground robot has a few dozen at most)");
  }
  checkJointGraph(xml, file);
  ParseMessages messages;
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(text);
  if (!model)
    throw InputError(
        file, "<robot>",
        "malformed URDF: " + (messages.first_error.empty() ? std::string("rejected by urdfdom")
                                                           : messages.first_error));
  return model;
}

// Where a URDF's <mesh filename> points: file:// stripped, relative to the URDF's folder; empty
// for package:// (which needs ROS).
std::filesystem::path meshPath(const std::string& filename, const std::filesystem::path& dir) {
  if (filename.rfind("package://", 0) == 0) return {};
  const std::string name = filename.rfind("file://", 0) == 0 ? filename.substr(7) : filename;
  const std::filesystem::path path(name);
  return path.is_relative() ? dir / path : path;
}

struct LinkMass {
  double mass = 0.0;
  double izz = 0.0;  // about the vertical axis through the base origin
};

// Converts one URDF robot; the state of one addUrdfVehicle call.
class UrdfConverter {
 public:
  UrdfConverter(XMLDocument& doc, const VehicleSpec& v)
      : doc_(doc),
        v_(v),
        file_(v.model_file.string()),
        prefix_(v.name + "/"),
        dir_(v.model_file.parent_path()) {}

  bool convert(XMLElement* worldbody, double floor_z) {
    model_ = parseUrdf(file_);
    urdf::LinkConstSharedPtr root = model_->getRoot();
    if (!root) throw InputError(file_, "<robot>", "no root link");

    // A massless, shapeless root with one planar child joint: a holonomic planar base.
    urdf::JointSharedPtr planar;
    if (!root->inertial && root->collision_array.empty() && root->visual_array.empty() &&
        root->child_joints.size() == 1 && root->child_joints[0]->type == urdf::Joint::PLANAR)
      planar = root->child_joints[0];
    urdf::LinkConstSharedPtr base = planar ? model_->getLink(planar->child_link_name) : root;

    XMLElement* body = add(doc_, worldbody, "body");
    body->SetAttribute("name", (prefix_ + "base").c_str());
    if (planar) {
      const Eigen::Vector3d axis = vec(planar->axis);
      const Eigen::Isometry3d origin = pose(planar->parent_to_joint_origin_transform);
      if ((origin.linear() * axis - Eigen::Vector3d::UnitZ()).norm() > 1e-6)
        throw InputError(file_, "joint '" + planar->name + "' <axis>",
                         "a planar base joint must have its axis vertical (0 0 1)");
      // The body sits at the start with the world's orientation, so that the slides run along
      // world x and y: root_x, root_y are displacements from the start and root_yaw is the
      // heading (the simulation sets the start heading; MuJoCo measures joints from qpos0).
      if (origin.translation().head<2>().norm() > 1e-9)
        throw InputError(file_, "joint '" + planar->name + "' <origin>",
                         "a planar base joint must have its origin at x = y = 0");
      body->SetAttribute(
          "pos", fmt3(v_.start.x(), v_.start.y(), floor_z + origin.translation().z()).c_str());
      addJoint(body, "root_x", "slide", "1 0 0");
      addJoint(body, "root_y", "slide", "0 1 0");
      addJoint(body, "root_yaw", "hinge", "0 0 1");
    } else {
      body->SetAttribute("pos", fmt3(v_.start.x(), v_.start.y(), floor_z).c_str());
      body->SetAttribute("euler", ("0 0 " + fmt(v_.yaw_deg)).c_str());
      add(doc_, body, "freejoint")->SetAttribute("name", (prefix_ + "root").c_str());
    }
    checkTreeDepth(*base);
    addLinkContents(body, *base, Eigen::Isometry3d::Identity());
    addDescendants(body, *base);

    if (planar)
      addHolonomicDrive(*planar, *base);
    else
      addDifferentialDrive(*base);
    return !planar;
  }

 private:
  void addJoint(XMLElement* body, const std::string& name, const char* type, const char* axis) {
    XMLElement* j = add(doc_, body, "joint");
    j->SetAttribute("name", (prefix_ + name).c_str());
    j->SetAttribute("type", type);
    j->SetAttribute("axis", axis);
  }

  std::string linkPlace(const urdf::Link& link, const char* what, std::size_t k) const {
    return "link '" + link.name + "' <" + what + "> " + std::to_string(k + 1);
  }

  // Inertial and geoms of one link; `in_base` is the link frame in the base frame (for the
  // drive's mass properties).
  void addLinkContents(XMLElement* body, const urdf::Link& link, const Eigen::Isometry3d& in_base) {
    if (link.inertial) {
      const urdf::Inertial& i = *link.inertial;
      if (!(i.mass > 0.0))
        throw InputError(file_, "link '" + link.name + "' <inertial> <mass>",
                         "mass must be positive");
      XMLElement* e = add(doc_, body, "inertial");
      e->SetAttribute("pos",
                      fmt3(i.origin.position.x, i.origin.position.y, i.origin.position.z).c_str());
      e->SetAttribute("mass", fmt(i.mass).c_str());
      // MuJoCo takes a full inertia only in the body frame: rotate it there, I_b = R I R^T.
      Eigen::Matrix3d I;
      I << i.ixx, i.ixy, i.ixz, i.ixy, i.iyy, i.iyz, i.ixz, i.iyz, i.izz;
      const Eigen::Matrix3d R = quat(i.origin.rotation).normalized().toRotationMatrix();
      I = R * I * R.transpose();
      e->SetAttribute(
          "fullinertia",
          (fmt3(I(0, 0), I(1, 1), I(2, 2)) + " " + fmt3(I(0, 1), I(0, 2), I(1, 2))).c_str());
      const Eigen::Vector3d c = in_base * vec(i.origin.position);
      mass_.mass += i.mass;
      mass_.izz += i.izz + i.mass * c.head<2>().squaredNorm();
    }
    const bool caster = link.name.find("caster") != std::string::npos;
    for (std::size_t k = 0; k < link.collision_array.size(); ++k) {
      const urdf::Collision& c = *link.collision_array[k];
      XMLElement* g = addGeom(body, link, "collision", k, c.origin, c.geometry);
      g->SetAttribute("name", (prefix_ + link.name + "/collision" + std::to_string(k)).c_str());
      // Drawn only when the link has no visual of its own (group 3 is hidden by default).
      if (!link.visual_array.empty()) g->SetAttribute("group", 3);
      g->SetAttribute("rgba", "0.5 0.5 0.5 1");
      if (caster) {
        // Frictionless: the caster's own settings win over the floor's (higher priority).
        g->SetAttribute("priority", 1);
        g->SetAttribute("condim", 1);
      }
      extendRadius(in_base, c.origin, *c.geometry);
    }
    for (std::size_t k = 0; k < link.visual_array.size(); ++k) {
      const urdf::Visual& vis = *link.visual_array[k];
      XMLElement* g = addGeom(body, link, "visual", k, vis.origin, vis.geometry);
      g->SetAttribute("name", (prefix_ + link.name + "/visual" + std::to_string(k)).c_str());
      g->SetAttribute("contype", 0);
      g->SetAttribute("conaffinity", 0);
      g->SetAttribute("group", 1);
      if (vis.material) {
        const urdf::Color& col = vis.material->color;
        g->SetAttribute("rgba", (fmt3(col.r, col.g, col.b) + " " + fmt(col.a)).c_str());
      }
    }
  }

  XMLElement* addGeom(XMLElement* body, const urdf::Link& link, const char* what, std::size_t k,
                      const urdf::Pose& origin, const urdf::GeometrySharedPtr& geometry) {
    const std::string place = linkPlace(link, what, k);
    if (!geometry) throw InputError(file_, place, "no <geometry>");
    XMLElement* g = add(doc_, body, "geom");
    setPose(g, origin);
    g->SetAttribute("mass", 0);  // masses come from the URDF inertials only
    switch (geometry->type) {
      case urdf::Geometry::BOX: {
        const auto& b = static_cast<const urdf::Box&>(*geometry);
        g->SetAttribute("type", "box");
        g->SetAttribute("size", fmt3(0.5 * b.dim.x, 0.5 * b.dim.y, 0.5 * b.dim.z).c_str());
        break;
      }
      case urdf::Geometry::CYLINDER: {
        // URDF and MuJoCo cylinders both lie along their frame's z axis.
        const auto& c = static_cast<const urdf::Cylinder&>(*geometry);
        g->SetAttribute("type", "cylinder");
        g->SetAttribute("size", (fmt(c.radius) + " " + fmt(0.5 * c.length)).c_str());
        break;
      }
      case urdf::Geometry::SPHERE: {
        const auto& s = static_cast<const urdf::Sphere&>(*geometry);
        g->SetAttribute("type", "sphere");
        g->SetAttribute("size", fmt(s.radius).c_str());
        break;
      }
      case urdf::Geometry::MESH: {
        const auto& m = static_cast<const urdf::Mesh&>(*geometry);
        const std::string mesh_place = place + " <mesh filename=\"" + m.filename + "\">";
        if (m.filename.rfind("package://", 0) == 0)
          throw InputError(file_, mesh_place,
                           "package:// mesh paths need ROS; give a path relative to the URDF file");
        const std::filesystem::path path = meshPath(m.filename, dir_);
        try {
          checkInputFile(path.string(), kMaxModelFileBytes, "mesh file");
        } catch (const InputError& e) {
          throw InputError(file_, mesh_place, "mesh " + path.string() + ": " + e.problem());
        }
        std::string ext = path.extension().string();
        for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        if (ext != ".stl" && ext != ".obj" && ext != ".msh")
          throw InputError(file_, mesh_place,
                           "unsupported mesh format '" + ext + "' (stl, obj, msh)");
        const std::string asset_name = prefix_ + "mesh" + std::to_string(mesh_count_++);
        XMLElement* a = add(doc_, section(doc_, "asset"), "mesh");
        a->SetAttribute("name", asset_name.c_str());
        a->SetAttribute("file", std::filesystem::absolute(path).c_str());
        a->SetAttribute("scale", fmt3(m.scale.x, m.scale.y, m.scale.z).c_str());
        g->SetAttribute("type", "mesh");
        g->SetAttribute("mesh", asset_name.c_str());
        break;
      }
    }
    return g;
  }

  // The base's horizontal rim radius: the farthest collision shape from the base's vertical axis
  // (bounding circles of boxes and cylinders, spheres).
  void extendRadius(const Eigen::Isometry3d& in_base, const urdf::Pose& origin,
                    const urdf::Geometry& g) {
    const Eigen::Isometry3d t = in_base * pose(origin);
    double r = 0.0;
    if (g.type == urdf::Geometry::BOX) {
      const auto& b = static_cast<const urdf::Box&>(g);
      r = 0.5 * Eigen::Vector3d(b.dim.x, b.dim.y, b.dim.z).norm();
    } else if (g.type == urdf::Geometry::CYLINDER) {
      const auto& c = static_cast<const urdf::Cylinder&>(g);
      r = std::hypot(c.radius, 0.5 * c.length);
    } else if (g.type == urdf::Geometry::SPHERE) {
      r = static_cast<const urdf::Sphere&>(g).radius;
    }
    rim_radius_ = std::max(rim_radius_, t.translation().head<2>().norm() + r);
  }

  // Refuses a tree deeper than kMaxUrdfDepth below the base, measured without recursion (urdfdom
  // accepts a chain of any length; MuJoCo's compiler recurses once per level).
  void checkTreeDepth(const urdf::Link& base) const {
    std::vector<std::pair<const urdf::Link*, std::size_t>> open = {{&base, 0}};
    while (!open.empty()) {
      const auto [link, depth] = open.back();
      open.pop_back();
      if (depth > kMaxUrdfDepth)
        throw InputError(
            file_, "link '" + link->name + "'",
            "more than " + std::to_string(kMaxUrdfDepth) + " links below the base on one branch");
      for (const auto& child : link->child_links) open.emplace_back(child.get(), depth + 1);
    }
  }

  // The bodies of every link below `base`, depth first and in the URDF's order of child joints
  // (as a recursive walk would make them), with an explicit stack.
  void addDescendants(XMLElement* base_body, const urdf::Link& base) {
    struct Pending {
      XMLElement* parent;
      const urdf::Joint* joint;
      Eigen::Isometry3d parent_in_base;
    };
    std::vector<Pending> open;
    const auto push = [&](XMLElement* parent, const urdf::Link& link, const Eigen::Isometry3d& at) {
      for (auto j = link.child_joints.rbegin(); j != link.child_joints.rend(); ++j)
        open.push_back({parent, j->get(), at});
    };
    push(base_body, base, Eigen::Isometry3d::Identity());
    while (!open.empty()) {
      const Pending p = open.back();
      open.pop_back();
      const auto [body, link, in_base] = addChild(p.parent, *p.joint, p.parent_in_base);
      push(body, *link, in_base);
    }
  }

  struct AddedBody {
    XMLElement* body;
    urdf::LinkConstSharedPtr link;
    Eigen::Isometry3d in_base;
  };

  // The body of joint `j`'s child link, under `parent`; its own children are the caller's.
  AddedBody addChild(XMLElement* parent, const urdf::Joint& j,
                     const Eigen::Isometry3d& parent_in_base) {
    urdf::LinkConstSharedPtr link = model_->getLink(j.child_link_name);
    if (!link)
      throw InputError(file_, "joint '" + j.name + "' <child>",
                       "no link '" + j.child_link_name + "'");
    XMLElement* body = add(doc_, parent, "body");
    body->SetAttribute("name", (prefix_ + link->name).c_str());
    setPose(body, j.parent_to_joint_origin_transform);
    const Eigen::Isometry3d in_base = parent_in_base * pose(j.parent_to_joint_origin_transform);
    const std::string axis = fmt3(j.axis.x, j.axis.y, j.axis.z);
    const std::string place = "joint '" + j.name + "'";
    switch (j.type) {
      case urdf::Joint::FIXED:
        break;  // a body without joints is welded to its parent
      case urdf::Joint::REVOLUTE:
      case urdf::Joint::CONTINUOUS:
      case urdf::Joint::PRISMATIC: {
        if (!link->inertial)
          throw InputError(file_, "link '" + link->name + "'", "a moving link needs an <inertial>");
        XMLElement* e = add(doc_, body, "joint");
        e->SetAttribute("name", (prefix_ + j.name).c_str());
        e->SetAttribute("type", j.type == urdf::Joint::PRISMATIC ? "slide" : "hinge");
        e->SetAttribute("axis", axis.c_str());
        if (j.type != urdf::Joint::CONTINUOUS && j.limits) {
          if (!(j.limits->lower < j.limits->upper))
            throw InputError(file_, place + " <limit>", "lower must be below upper");
          // URDF angles are radians; the composed model reads angles in degrees.
          const double k = j.type == urdf::Joint::REVOLUTE ? 180.0 / M_PI : 1.0;
          e->SetAttribute("range",
                          (fmt(k * j.limits->lower) + " " + fmt(k * j.limits->upper)).c_str());
        }
        if (j.dynamics) {
          e->SetAttribute("damping", fmt(j.dynamics->damping).c_str());
          e->SetAttribute("frictionloss", fmt(j.dynamics->friction).c_str());
        }
        break;
      }
      default:
        throw InputError(file_, place,
                         "joint type not supported below the base (fixed, revolute, "
                         "continuous, prismatic)");
    }
    if (j.type == urdf::Joint::CONTINUOUS) continuous_.push_back(&j);
    addLinkContents(body, *link, in_base);
    return {body, link, in_base};
  }

  // A velocity servo on `joint`: force kv (command - joint speed), kv = inertia / time constant,
  // the command held within +-speed and the force within +-force. sim/ applies it (no MuJoCo
  // actuator: each would cost an nv-long row of the actuator moment matrix every step).
  void addVelocityServo(const std::string& joint, double inertia, double force, double speed) {
    // Appended piece by piece: GCC 12's -Wrestrict misfires on operator+ chains.
    if (!servo_joints_.empty()) servo_joints_ += ' ';
    servo_joints_ += prefix_;
    servo_joints_ += joint;
    for (double x : {inertia / kDriveTimeConstant, force, speed}) {
      if (!servo_data_.empty()) servo_data_ += ' ';
      servo_data_ += fmt(x);
    }
  }

  void requireLimit(const urdf::Joint& j) const {
    if (!j.limits || !(j.limits->effort > 0) || !(j.limits->velocity > 0))
      throw InputError(
          file_, "joint '" + j.name + "' <limit>",
          "a driven joint needs <limit effort=\"...\" velocity=\"...\"> (both positive)");
  }

  void recordDrive(const GroundDrive& d) {
    XMLElement* custom = section(doc_, "custom");
    XMLElement* servos = add(doc_, custom, "numeric");
    servos->SetAttribute("name", (prefix_ + "drive_servos").c_str());
    servos->SetAttribute("data", servo_data_.c_str());
    XMLElement* joints = add(doc_, custom, "text");
    joints->SetAttribute("name", (prefix_ + "drive_joints").c_str());
    joints->SetAttribute("data", servo_joints_.c_str());
    XMLElement* n = add(doc_, custom, "numeric");
    n->SetAttribute("name", (prefix_ + "ground_drive").c_str());
    n->SetAttribute(
        "data",
        (fmt(d.kind == GroundDrive::Kind::Holonomic ? 0 : 1) + " " + fmt(d.planar_root ? 1 : 0) +
         " " + fmt3(d.max_speed, d.max_yaw_rate, d.wheel_radius) + " " + fmt(d.wheel_separation))
            .c_str());
  }

  void addHolonomicDrive(const urdf::Joint& planar, const urdf::Link& base) {
    requireLimit(planar);
    if (!base.inertial)
      throw InputError(file_, "link '" + base.name + "'", "the base needs an <inertial>");
    if (!(rim_radius_ > 0))
      throw InputError(file_, "link '" + base.name + "'", "the base needs a <collision> shape");
    const double force = planar.limits->effort, speed = planar.limits->velocity;
    addVelocityServo("root_x", mass_.mass, force, speed);
    addVelocityServo("root_y", mass_.mass, force, speed);
    // The drive force acting at the rim turns the base; the rim moving at full speed bounds the
    // yaw rate.
    addVelocityServo("root_yaw", mass_.izz, force * rim_radius_, speed / rim_radius_);
    GroundDrive d;
    d.kind = GroundDrive::Kind::Holonomic;
    d.planar_root = true;
    d.max_speed = speed;
    d.max_yaw_rate = speed / rim_radius_;
    recordDrive(d);
  }

  void addDifferentialDrive(const urdf::Link& base) {
    const urdf::Joint* left = nullptr;
    const urdf::Joint* right = nullptr;
    for (const urdf::Joint* j : continuous_) {
      if (j->name.find("left_wheel") != std::string::npos) left = left ? nullptr : j;
      if (j->name.find("right_wheel") != std::string::npos) right = right ? nullptr : j;
    }
    if (!left || !right)
      throw InputError(file_, "link '" + base.name + "'",
                       "a ground robot needs a planar root joint (holonomic) or exactly one "
                       "continuous joint named *left_wheel* and one *right_wheel* (differential)");
    double radius = 0.0;
    for (const urdf::Joint* j : {left, right}) {
      requireLimit(*j);
      const urdf::LinkConstSharedPtr wheel = model_->getLink(j->child_link_name);
      for (const auto& c : wheel->collision_array)
        if (c->geometry && c->geometry->type == urdf::Geometry::CYLINDER)
          radius = std::max(radius, static_cast<const urdf::Cylinder&>(*c->geometry).radius);
      if (!(radius > 0))
        throw InputError(file_, "link '" + wheel->name + "' <collision>",
                         "a wheel needs a cylinder collision shape");
    }
    const Eigen::Vector3d l = vec(left->parent_to_joint_origin_transform.position);
    const Eigen::Vector3d r = vec(right->parent_to_joint_origin_transform.position);
    const double separation = (l - r).head<2>().norm();
    if (!(separation > 0))
      throw InputError(file_, "joint '" + left->name + "' <origin>",
                       "the wheels must not coincide");
    const urdf::Inertial& wi = *model_->getLink(left->child_link_name)->inertial;
    // Each wheel drives half the robot's mass plus its own spin inertia.
    const double inertia = 0.5 * mass_.mass * radius * radius + wi.iyy;
    const double speed = std::min(left->limits->velocity, right->limits->velocity);
    addVelocityServo(left->name, inertia, left->limits->effort, left->limits->velocity);
    addVelocityServo(right->name, inertia, right->limits->effort, right->limits->velocity);
    GroundDrive d;
    d.kind = GroundDrive::Kind::Differential;
    d.max_speed = speed * radius;
    d.max_yaw_rate = 2.0 * d.max_speed / separation;
    d.wheel_radius = radius;
    d.wheel_separation = separation;
    recordDrive(d);
  }

  XMLDocument& doc_;
  const VehicleSpec& v_;
  std::string file_, prefix_;
  std::filesystem::path dir_;
  urdf::ModelInterfaceSharedPtr model_;
  LinkMass mass_;
  double rim_radius_ = 0.0;
  int mesh_count_ = 0;
  std::vector<const urdf::Joint*> continuous_;
  std::string servo_joints_, servo_data_;  // the drive's servos, in drive order
};

}  // namespace

std::vector<std::filesystem::path> urdfMeshFiles(const std::filesystem::path& urdf) {
  std::vector<std::filesystem::path> files;
  XMLDocument xml;
  try {
    const std::string text = readInputFile(urdf.string(), kMaxModelFileBytes, "URDF file");
    if (xml.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) return files;
  } catch (const InputError&) {
    return files;
  }
  std::vector<const XMLElement*> open = {xml.RootElement()};
  while (!open.empty() && open.back()) {
    const XMLElement* e = open.back();
    open.pop_back();
    if (const char* f = e->Attribute("filename"); f && std::strcmp(e->Name(), "mesh") == 0)
      if (const auto p = meshPath(f, urdf.parent_path()); !p.empty()) files.push_back(p);
    for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement())
      open.push_back(c);
  }
  return files;
}

bool addUrdfVehicle(XMLDocument& doc, XMLElement* worldbody, const VehicleSpec& vehicle,
                    double floor_z) {
  return UrdfConverter(doc, vehicle).convert(worldbody, floor_z);
}

bool readGroundDrive(const mjModel* m, const std::string& vehicle_name, GroundDrive& d) {
  const int id = mj_name2id(m, mjOBJ_NUMERIC, (vehicle_name + "/ground_drive").c_str());
  if (id < 0 || m->numeric_size[id] != 6) return false;
  const mjtNum* x = m->numeric_data + m->numeric_adr[id];
  d.kind = x[0] == 0 ? GroundDrive::Kind::Holonomic : GroundDrive::Kind::Differential;
  d.planar_root = x[1] != 0;
  d.max_speed = x[2];
  d.max_yaw_rate = x[3];
  d.wheel_radius = x[4];
  d.wheel_separation = x[5];
  const int servos = mj_name2id(m, mjOBJ_NUMERIC, (vehicle_name + "/drive_servos").c_str());
  const int joints = mj_name2id(m, mjOBJ_TEXT, (vehicle_name + "/drive_joints").c_str());
  const int count = d.kind == GroundDrive::Kind::Holonomic ? 3 : 2;
  if (servos < 0 || joints < 0 || m->numeric_size[servos] != 3 * count) return false;
  std::istringstream names(std::string(m->text_data + m->text_adr[joints]));
  const mjtNum* s = m->numeric_data + m->numeric_adr[servos];
  d.servo_count = count;
  for (int i = 0; i < count; ++i) {
    std::string joint;
    names >> joint;
    const int id = mj_name2id(m, mjOBJ_JOINT, joint.c_str());
    if (id < 0) return false;
    d.servos[i] = {m->jnt_dofadr[id], s[3 * i], s[3 * i + 1], s[3 * i + 2]};
  }
  return true;
}

}  // namespace cosim
