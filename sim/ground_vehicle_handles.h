#pragma once
// Where a ground robot (sim/urdf_vehicle.h) lives in the compiled model: its root joints, drive
// actuators, geoms and horizontal radius; and how to pose a planar base.
#include "sim/world_model.h"

namespace cosim {

// Fills h (h.name and h.body already set). Throws InputError naming the URDF file if the model
// lacks what addUrdfVehicle should have made.
void readGroundVehicleHandles(const mjModel* m, const VehicleSpec& v, VehicleHandles& h);

// Puts a planar base (h.drive.planar_root) at world (x, y) with heading yaw: its root joints
// measure displacement from the start (MuJoCo counts joints from qpos0).
void setPlanarPose(mjData* d, const VehicleHandles& h, const Eigen::Vector2d& xy, double yaw);

}  // namespace cosim
