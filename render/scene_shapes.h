#pragma once
// The geometry of a composed world as plain shapes (box, cylinder, sphere, capsule, ellipsoid),
// read off the MuJoCo model: what a run's 3D replay (viewer.html) and its MCAP export draw.
// The model is the one truth: scenario obstacles, an included MJCF fragment's geoms, grid-map
// blocks and each vehicle's own geoms all come out the same way.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "sim/world_model.h"

namespace cosim {

enum class ShapeKind { Box, Cylinder, Sphere, Capsule, Ellipsoid };

// "box", "cylinder", "sphere", "capsule", "ellipsoid".
const char* shapeKindName(ShapeKind kind);

struct SceneShape {
  ShapeKind kind = ShapeKind::Box;
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();  // centre, in the frame the list is given in
  Eigen::Quaterniond rot = Eigen::Quaterniond::Identity();
  // Full extents along the shape's own axes: a box's edges; a cylinder's or capsule's diameter
  // (x, y) and the length of its straight part along z; a sphere's or ellipsoid's diameters. A
  // mesh geom comes out as the box around its vertices.
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  Eigen::Vector4f rgba = Eigen::Vector4f::Ones();
};

// Every static geom of the world (scenario obstacles, fragment and grid-map geometry) in world
// coordinates, without the floor plane and without the vehicles and moving obstacles.
std::vector<SceneShape> staticWorldShapes(const WorldModel& world);

// The geoms of vehicle `v` (world.vehicles()[v]) in the frame its logged pose is given in: the
// root body's frame, raised by the fixed height of a planar ground robot (logged at z = 0).
std::vector<SceneShape> vehicleShapes(const WorldModel& world, std::size_t v);

// The geoms of the moving obstacle body `name` ("moving<i>") in its own frame, whose logged
// centre moves it. Empty if the model has no such body.
std::vector<SceneShape> movingObstacleShapes(const WorldModel& world, const std::string& name);

}  // namespace cosim
