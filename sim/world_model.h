#pragma once
// Composes one MuJoCo model from a scenario: world bounds (floor), the scenario's obstacles as
// static geoms (the same Obstacle values the planners see), an optional MJCF include, and each
// vehicle's model file with its names prefixed by the vehicle name. Owns the mjModel.
#include <mujoco/mujoco.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "control/quadrotor_params.h"
#include "sim/scenario.h"
#include "sim/urdf_vehicle.h"

namespace cosim {

// Where a vehicle lives inside the composed model.
struct VehicleHandles {
  std::string name;
  int body = -1;           // the vehicle's root body ("<name>/base")
  int qpos_adr = -1;       // its free joint's qpos (x y z qw qx qy qz)
  int qvel_adr = -1;       // its free joint's qvel (world linear, body angular)
  std::vector<int> geoms;  // every geom of the vehicle (for contacts)
  QuadrotorParams params;  // read off the model: mass, inertia, rotors, limits, radius
  // vehicles[i].airframe's IMU noise densities for this vehicle (unset: sensors.imu's).
  std::optional<double> gyro_noise, accel_noise;
  // Ground robots (sim/urdf_vehicle.h): drive has the drive's servos (x, y, yaw of a holonomic
  // base; left and right wheel of a differential one); with a planar root, qpos_adr and
  // qvel_adr point at root_x, root_y, root_yaw; params has mass, radius (horizontal) and gravity.
  VehicleKind kind = VehicleKind::Quadrotor;
  GroundDrive drive;
};

class WorldModel {
 public:
  // Throws InputError naming the model file if a vehicle model is malformed or violates the
  // conventions of models/ (see models/quad_1500g.xml).
  static WorldModel build(const Scenario& scenario);
  static WorldModel fromXml(const std::string& xml, const Scenario& scenario);

  mjModel* model() const { return model_.get(); }
  const std::string& xml() const { return xml_; }
  const std::vector<VehicleHandles>& vehicles() const { return vehicles_; }
  int floorGeom() const { return floor_geom_; }

 private:
  struct ModelDeleter {
    void operator()(mjModel* m) const { mj_deleteModel(m); }
  };
  std::unique_ptr<mjModel, ModelDeleter> model_;
  std::string xml_;
  std::vector<VehicleHandles> vehicles_;
  int floor_geom_ = -1;
};

// The composed MJCF text (exposed for tests and for logging next to a run).
std::string composeWorldXml(const Scenario& scenario);

}  // namespace cosim
