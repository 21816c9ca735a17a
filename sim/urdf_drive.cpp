#include "sim/urdf_drive.h"

#include <algorithm>
#include <sstream>
#include <utility>

#include "core/input_error.h"
#include "sim/urdf_mjcf.h"
#include "sim/urdf_vehicle.h"

namespace cosim {

using namespace urdf_mjcf;
using tinyxml2::XMLElement;

namespace {

// The drive's velocity servos settle like a first-order lag of this time constant (about 0.15 s
// to 95 %), typical of a small robot's motor-driver speed loop; design value. A servo's gain is
// the driven inertia divided by it, so every robot responds alike whatever its size.
constexpr double kDriveTimeConstant = 0.05;

}  // namespace

UrdfDrive::UrdfDrive(tinyxml2::XMLDocument& doc, const urdf::ModelInterface& model,
                     std::string file, std::string prefix)
    : doc_(doc), model_(model), file_(std::move(file)), prefix_(std::move(prefix)) {}

void UrdfDrive::addVelocityServo(const std::string& joint, double inertia, double force,
                                 double speed) {
  // Appended piece by piece: GCC 12's -Wrestrict misfires on operator+ chains.
  if (!servo_joints_.empty()) servo_joints_ += ' ';
  servo_joints_ += prefix_;
  servo_joints_ += joint;
  for (double x : {inertia / kDriveTimeConstant, force, speed}) {
    if (!servo_data_.empty()) servo_data_ += ' ';
    servo_data_ += tenSignificantDigits(x);
  }
}

void UrdfDrive::requireLimit(const urdf::Joint& j) const {
  if (!j.limits || !(j.limits->effort > 0) || !(j.limits->velocity > 0))
    throw InputError(
        file_, "joint '" + j.name + "' <limit>",
        "a driven joint needs <limit effort=\"...\" velocity=\"...\"> (both positive)");
}

void UrdfDrive::recordDrive(const GroundDrive& d) {
  XMLElement* custom = section(doc_, "custom");
  XMLElement* servos = add(doc_, custom, "numeric");
  servos->SetAttribute("name", (prefix_ + "drive_servos").c_str());
  servos->SetAttribute("data", servo_data_.c_str());
  XMLElement* joints = add(doc_, custom, "text");
  joints->SetAttribute("name", (prefix_ + "drive_joints").c_str());
  joints->SetAttribute("data", servo_joints_.c_str());
  XMLElement* n = add(doc_, custom, "numeric");
  n->SetAttribute("name", (prefix_ + "ground_drive").c_str());
  n->SetAttribute("data", (tenSignificantDigits(d.kind == GroundDrive::Kind::Holonomic ? 0 : 1) +
                           " " + tenSignificantDigits(d.planar_root ? 1 : 0) + " " +
                           fmt3(d.max_speed, d.max_yaw_rate, d.wheel_radius) + " " +
                           tenSignificantDigits(d.wheel_separation))
                              .c_str());
}

void UrdfDrive::addHolonomic(const urdf::Joint& planar, const urdf::Link& base,
                             const UrdfLinkTree& links) {
  const LinkMass& mass = links.mass();
  const double rim_radius = links.rimRadius();
  requireLimit(planar);
  if (!base.inertial)
    throw InputError(file_, "link '" + base.name + "'", "the base needs an <inertial>");
  if (!(rim_radius > 0))
    throw InputError(file_, "link '" + base.name + "'", "the base needs a <collision> shape");
  const double force = planar.limits->effort, speed = planar.limits->velocity;
  addVelocityServo("root_x", mass.mass, force, speed);
  addVelocityServo("root_y", mass.mass, force, speed);
  // The drive force acting at the rim turns the base; the rim moving at full speed bounds the
  // yaw rate.
  addVelocityServo("root_yaw", mass.izz, force * rim_radius, speed / rim_radius);
  GroundDrive d;
  d.kind = GroundDrive::Kind::Holonomic;
  d.planar_root = true;
  d.max_speed = speed;
  d.max_yaw_rate = speed / rim_radius;
  recordDrive(d);
}

void UrdfDrive::addDifferential(const urdf::Link& base, const UrdfLinkTree& links) {
  const urdf::Joint* left = nullptr;
  const urdf::Joint* right = nullptr;
  for (const urdf::Joint* j : links.continuousJoints()) {
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
    const urdf::LinkConstSharedPtr wheel = model_.getLink(j->child_link_name);
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
    throw InputError(file_, "joint '" + left->name + "' <origin>", "the wheels must not coincide");
  const urdf::Inertial& wi = *model_.getLink(left->child_link_name)->inertial;
  // Each wheel drives half the robot's mass plus its own spin inertia.
  const double inertia = 0.5 * links.mass().mass * radius * radius + wi.iyy;
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
