#include "sim/urdf_vehicle.h"

#include "core/input_error.h"
#include "sim/urdf_drive.h"
#include "sim/urdf_file.h"
#include "sim/urdf_link_tree.h"
#include "sim/urdf_mjcf.h"

namespace cosim {

using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

namespace {

void addJoint(XMLDocument& doc, XMLElement* body, const std::string& name, const char* type,
              const char* axis) {
  XMLElement* j = urdf_mjcf::add(doc, body, "joint");
  j->SetAttribute("name", name.c_str());
  j->SetAttribute("type", type);
  j->SetAttribute("axis", axis);
}

}  // namespace

bool addUrdfVehicle(XMLDocument& doc, XMLElement* worldbody, const VehicleSpec& vehicle,
                    double floor_z) {
  const std::string file = vehicle.model_file.string(), prefix = vehicle.name + "/";
  const urdf::ModelInterfaceSharedPtr model = parseUrdf(file);
  urdf::LinkConstSharedPtr root = model->getRoot();
  if (!root) throw InputError(file, "<robot>", "no root link");

  // A massless, shapeless root with one planar child joint: a holonomic planar base.
  urdf::JointSharedPtr planar;
  if (!root->inertial && root->collision_array.empty() && root->visual_array.empty() &&
      root->child_joints.size() == 1 && root->child_joints[0]->type == urdf::Joint::PLANAR)
    planar = root->child_joints[0];
  urdf::LinkConstSharedPtr base = planar ? model->getLink(planar->child_link_name) : root;

  XMLElement* body = urdf_mjcf::add(doc, worldbody, "body");
  body->SetAttribute("name", (prefix + "base").c_str());
  if (planar) {
    const Eigen::Vector3d axis = urdf_mjcf::vec(planar->axis);
    const Eigen::Isometry3d origin = urdf_mjcf::pose(planar->parent_to_joint_origin_transform);
    if ((origin.linear() * axis - Eigen::Vector3d::UnitZ()).norm() > 1e-6)
      throw InputError(file, "joint '" + planar->name + "' <axis>",
                       "a planar base joint must have its axis vertical (0 0 1)");
    // The body sits at the start with the world's orientation, so that the slides run along
    // world x and y: root_x, root_y are displacements from the start and root_yaw is the
    // heading (the simulation sets the start heading; MuJoCo measures joints from qpos0).
    if (origin.translation().head<2>().norm() > 1e-9)
      throw InputError(file, "joint '" + planar->name + "' <origin>",
                       "a planar base joint must have its origin at x = y = 0");
    body->SetAttribute("pos", urdf_mjcf::fmt3(vehicle.start.x(), vehicle.start.y(),
                                              floor_z + origin.translation().z())
                                  .c_str());
    addJoint(doc, body, prefix + "root_x", "slide", "1 0 0");
    addJoint(doc, body, prefix + "root_y", "slide", "0 1 0");
    addJoint(doc, body, prefix + "root_yaw", "hinge", "0 0 1");
  } else {
    body->SetAttribute("pos",
                       urdf_mjcf::fmt3(vehicle.start.x(), vehicle.start.y(), floor_z).c_str());
    body->SetAttribute("euler", ("0 0 " + tenSignificantDigits(vehicle.yaw_deg)).c_str());
    urdf_mjcf::add(doc, body, "freejoint")->SetAttribute("name", (prefix + "root").c_str());
  }
  UrdfLinkTree links(doc, *model, file, prefix, vehicle.model_file.parent_path());
  links.addBase(body, *base);

  UrdfDrive drive(doc, *model, file, prefix);
  if (planar)
    drive.addHolonomic(*planar, *base, links);
  else
    drive.addDifferential(*base, links);
  return !planar;
}

}  // namespace cosim
