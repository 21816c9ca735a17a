#include "sim/urdf_link_tree.h"

#include <cmath>
#include <utility>

#include "core/input_error.h"
#include "core/input_file.h"
#include "sim/urdf_file.h"
#include "sim/urdf_mjcf.h"

namespace cosim {

using namespace urdf_mjcf;
using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

namespace {

// The deepest a ground robot's tree may be below its base (a design value, far above real
// robots: a mobile manipulator has about 10 levels). It also stays below the 100 levels of XML
// that tinyxml2, the parser MuJoCo reads the composed world with, accepts.
constexpr std::size_t kMaxUrdfDepth = 64;

}  // namespace

UrdfLinkTree::UrdfLinkTree(XMLDocument& doc, const urdf::ModelInterface& model, std::string file,
                           std::string prefix, std::filesystem::path dir)
    : doc_(doc),
      model_(model),
      file_(std::move(file)),
      prefix_(std::move(prefix)),
      dir_(std::move(dir)) {}

void UrdfLinkTree::addBase(XMLElement* body, const urdf::Link& base) {
  checkTreeDepth(base);
  addLinkContents(body, base, Eigen::Isometry3d::Identity());
  addDescendants(body, base);
}

std::string UrdfLinkTree::linkPlace(const urdf::Link& link, const char* what, std::size_t k) const {
  return "link '" + link.name + "' <" + what + "> " + std::to_string(k + 1);
}

void UrdfLinkTree::addLinkContents(XMLElement* body, const urdf::Link& link,
                                   const Eigen::Isometry3d& in_base) {
  if (link.inertial) {
    const urdf::Inertial& i = *link.inertial;
    if (!(i.mass > 0.0))
      throw InputError(file_, "link '" + link.name + "' <inertial> <mass>",
                       "mass must be positive");
    XMLElement* e = add(doc_, body, "inertial");
    e->SetAttribute("pos",
                    fmt3(i.origin.position.x, i.origin.position.y, i.origin.position.z).c_str());
    e->SetAttribute("mass", tenSignificantDigits(i.mass).c_str());
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
      g->SetAttribute("rgba",
                      (fmt3(col.r, col.g, col.b) + " " + tenSignificantDigits(col.a)).c_str());
    }
  }
}

XMLElement* UrdfLinkTree::addGeom(XMLElement* body, const urdf::Link& link, const char* what,
                                  std::size_t k, const urdf::Pose& origin,
                                  const urdf::GeometrySharedPtr& geometry) {
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
      g->SetAttribute(
          "size",
          (tenSignificantDigits(c.radius) + " " + tenSignificantDigits(0.5 * c.length)).c_str());
      break;
    }
    case urdf::Geometry::SPHERE: {
      const auto& s = static_cast<const urdf::Sphere&>(*geometry);
      g->SetAttribute("type", "sphere");
      g->SetAttribute("size", tenSignificantDigits(s.radius).c_str());
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

void UrdfLinkTree::extendRadius(const Eigen::Isometry3d& in_base, const urdf::Pose& origin,
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

void UrdfLinkTree::checkTreeDepth(const urdf::Link& base) const {
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

void UrdfLinkTree::addDescendants(XMLElement* base_body, const urdf::Link& base) {
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

UrdfLinkTree::AddedBody UrdfLinkTree::addChild(XMLElement* parent, const urdf::Joint& j,
                                               const Eigen::Isometry3d& parent_in_base) {
  urdf::LinkConstSharedPtr link = model_.getLink(j.child_link_name);
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
        e->SetAttribute("range", (tenSignificantDigits(k * j.limits->lower) + " " +
                                  tenSignificantDigits(k * j.limits->upper))
                                     .c_str());
      }
      if (j.dynamics) {
        e->SetAttribute("damping", tenSignificantDigits(j.dynamics->damping).c_str());
        e->SetAttribute("frictionloss", tenSignificantDigits(j.dynamics->friction).c_str());
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

}  // namespace cosim
