#pragma once
// The bodies of a URDF ground robot's links (part of the URDF conversion, sim/urdf_vehicle.h):
// each link a MuJoCo body with its inertial, its collision shapes as colliding geoms, its visuals
// as drawn-only geoms (meshes become assets), each joint below the base a MuJoCo joint. Gathers
// what the drive is sized from: the robot's mass and vertical inertia about the base, the base's
// rim radius and the continuous joints (the wheels).
#include <tinyxml2.h>
#include <urdf_model/model.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <string>
#include <vector>

namespace cosim {

struct LinkMass {
  double mass = 0.0;
  double izz = 0.0;  // about the vertical axis through the base origin
};

class UrdfLinkTree {
 public:
  // `file`: the URDF (for messages; `dir` is its folder, where meshes are looked for); `prefix`
  // starts every MuJoCo name ("robot1/").
  UrdfLinkTree(tinyxml2::XMLDocument& doc, const urdf::ModelInterface& model, std::string file,
               std::string prefix, std::filesystem::path dir);

  // Gives the base body `body` the base link's inertial and geoms, and adds every link below it
  // as bodies inside it. Throws InputError naming the URDF file and the link or joint for a tree
  // too deep, a moving link without an <inertial>, a bad <limit>, an unusable mesh or a joint
  // type not supported below the base.
  void addBase(tinyxml2::XMLElement* body, const urdf::Link& base);

  const LinkMass& mass() const { return mass_; }
  double rimRadius() const { return rim_radius_; }
  const std::vector<const urdf::Joint*>& continuousJoints() const { return continuous_; }

 private:
  std::string linkPlace(const urdf::Link& link, const char* what, std::size_t k) const;
  // Inertial and geoms of one link; `in_base` is the link frame in the base frame (for the
  // drive's mass properties).
  void addLinkContents(tinyxml2::XMLElement* body, const urdf::Link& link,
                       const Eigen::Isometry3d& in_base);
  tinyxml2::XMLElement* addGeom(tinyxml2::XMLElement* body, const urdf::Link& link,
                                const char* what, std::size_t k, const urdf::Pose& origin,
                                const urdf::GeometrySharedPtr& geometry);
  // The base's horizontal rim radius: the farthest collision shape from the base's vertical axis
  // (bounding circles of boxes and cylinders, spheres).
  void extendRadius(const Eigen::Isometry3d& in_base, const urdf::Pose& origin,
                    const urdf::Geometry& g);
  // Refuses a tree deeper than kMaxUrdfDepth below the base, measured without recursion (urdfdom
  // accepts a chain of any length; MuJoCo's compiler recurses once per level).
  void checkTreeDepth(const urdf::Link& base) const;
  // The bodies of every link below `base`, depth first and in the URDF's order of child joints
  // (as a recursive walk would make them), with an explicit stack.
  void addDescendants(tinyxml2::XMLElement* base_body, const urdf::Link& base);

  struct AddedBody {
    tinyxml2::XMLElement* body;
    urdf::LinkConstSharedPtr link;
    Eigen::Isometry3d in_base;
  };

  // The body of joint `j`'s child link, under `parent`; its own children are the caller's.
  AddedBody addChild(tinyxml2::XMLElement* parent, const urdf::Joint& j,
                     const Eigen::Isometry3d& parent_in_base);

  tinyxml2::XMLDocument& doc_;
  const urdf::ModelInterface& model_;
  std::string file_, prefix_;
  std::filesystem::path dir_;
  LinkMass mass_;
  double rim_radius_ = 0.0;
  int mesh_count_ = 0;
  std::vector<const urdf::Joint*> continuous_;
};

}  // namespace cosim
