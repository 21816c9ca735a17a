#pragma once
// The drive of a URDF ground robot (part of the URDF conversion, sim/urdf_vehicle.h): velocity
// servos on a planar base's x, y and yaw (holonomic) or on its two wheels (differential), sized
// from the robot's mass and the joints' <limit>s and recorded in the document's <custom> section,
// where readGroundDrive finds them in the compiled model; sim/physics_stepper.h applies them.
#include <tinyxml2.h>
#include <urdf_model/model.h>

#include <string>

#include "sim/urdf_link_tree.h"

namespace cosim {

struct GroundDrive;  // sim/urdf_vehicle.h

class UrdfDrive {
 public:
  // `file`: the URDF (for messages); `prefix` starts every MuJoCo name ("robot1/").
  UrdfDrive(tinyxml2::XMLDocument& doc, const urdf::ModelInterface& model, std::string file,
            std::string prefix);

  // Servos on root_x, root_y and root_yaw, from the planar joint's <limit> and the base's rim.
  void addHolonomic(const urdf::Joint& planar, const urdf::Link& base, const UrdfLinkTree& links);
  // Servos on the continuous joints named *left_wheel* and *right_wheel*.
  void addDifferential(const urdf::Link& base, const UrdfLinkTree& links);

 private:
  // A velocity servo on `joint`: force kv (command - joint speed), kv = inertia / time constant,
  // the command held within +-speed and the force within +-force. sim/ applies it (no MuJoCo
  // actuator: each would cost an nv-long row of the actuator moment matrix every step).
  void addVelocityServo(const std::string& joint, double inertia, double force, double speed);
  void requireLimit(const urdf::Joint& j) const;
  void recordDrive(const GroundDrive& d);

  tinyxml2::XMLDocument& doc_;
  const urdf::ModelInterface& model_;
  std::string file_, prefix_;
  std::string servo_joints_, servo_data_;  // the drive's servos, in drive order
};

}  // namespace cosim
