#pragma once
// What a vehicle is, which decides how it is built, planned, driven and measured: a quadrotor
// (an MJCF model from models/, flies in 3-D under a flight controller) or a ground robot (a
// URDF, drives in the floor plane z = 0 under sim/ground_pilot_step.h).
namespace cosim {

enum class VehicleKind { Quadrotor, GroundRobot };

}  // namespace cosim
