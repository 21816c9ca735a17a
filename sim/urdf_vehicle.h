#pragma once
// Ground robots described in URDF (read with urdfdom), turned into MuJoCo bodies for the composed
// world: links become bodies (with their inertials), joints become MuJoCo joints, collision shapes
// become colliding geoms and visuals become drawn-only geoms; then the actuators URDF cannot
// express are added. Conventions (see models/omni_base.urdf and models/diff_drive.urdf):
// - every MuJoCo name is prefixed "<vehicle>/"; the base body is "<vehicle>/base";
// - a root link without mass or geometry joined to the base by a planar joint (axis z) makes a
//   holonomic base: slide joints root_x, root_y and hinge root_yaw, driven by velocity servos
//   in x, y and yaw (force and speed from the planar joint's <limit>);
// - otherwise the root link is the base and gets a free joint "root"; it must then have two
//   continuous joints named *left_wheel* and *right_wheel* (a differential drive), driven by
//   velocity servos on the left and right wheel (torque and speed from their <limit>);
// - the servos are sim/'s (sim/physics_stepper.h applies them every physics step), recorded in
//   the model's <custom> section, not MuJoCo actuators;
// - links named *caster* touch the floor without friction (a ball caster rolls every way).
// The robot's URDF frame lies on the floor (REP 120 base_footprint): its origin is placed at the
// vehicle's start (x, y) on the floor.
#include <mujoco/mujoco.h>
#include <tinyxml2.h>

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <vector>

#include "sim/scenario.h"

namespace cosim {

// How a ground robot moves, read back from the compiled model.
struct GroundDrive {
  enum class Kind { Holonomic, Differential };
  Kind kind = Kind::Holonomic;
  bool planar_root = false;       // root dofs: slide x, slide y, hinge yaw (else a free joint)
  double max_speed = 0.0;         // m/s
  double max_yaw_rate = 0.0;      // rad/s
  double wheel_radius = 0.0;      // m (differential)
  double wheel_separation = 0.0;  // m (differential)
  // Planar root: the world (x, y) where root_x = root_y = 0, and the start heading (rad).
  Eigen::Vector2d planar_origin = Eigen::Vector2d::Zero();
  double start_yaw = 0.0;
  // Velocity servos: force kv (command - qvel[dof]), the command within +-max_speed and the force
  // within +-max_force (the MuJoCo velocity actuator's law). Holonomic: x, y, yaw; differential:
  // left wheel, right wheel.
  struct Servo {
    int dof = -1;
    double kv = 0.0;
    double max_force = 0.0;
    double max_speed = 0.0;
  };
  std::array<Servo, 3> servos{};
  int servo_count = 0;
};

// Appends the robot's bodies to `worldbody`, its meshes to the document's <asset> and its drive
// (servos included) to <custom>. Throws InputError naming the URDF file and the element for a
// malformed URDF, a missing mesh or a robot that breaks the conventions above. Returns whether
// the robot rests on the floor (a free base on wheels; a planar base floats above it).
bool addUrdfVehicle(tinyxml2::XMLDocument& doc, tinyxml2::XMLElement* worldbody,
                    const VehicleSpec& vehicle, double floor_z);

// The mesh files a URDF names (resolved as addUrdfVehicle resolves them), for fingerprints of
// what a run reads; nothing for a file that cannot be read (the run reports that).
std::vector<std::filesystem::path> urdfMeshFiles(const std::filesystem::path& urdf);

// The drive that addUrdfVehicle recorded for `vehicle_name` in the compiled model; false if
// there is none (not a ground robot).
bool readGroundDrive(const mjModel* m, const std::string& vehicle_name, GroundDrive& drive);

}  // namespace cosim
