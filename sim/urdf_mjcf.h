#pragma once
// What the URDF conversion (sim/urdf_vehicle.h) writes MJCF with: numbers as MJCF text (ten
// significant digits), elements appended to a parent or to a top-level section of the document,
// and URDF's vectors, rotations and poses as Eigen values and as MJCF pos and quat attributes.
#include <tinyxml2.h>
#include <urdf_model/pose.h>

#include <Eigen/Geometry>
#include <string>

#include "core/decimal_text.h"

namespace cosim::urdf_mjcf {

std::string fmt3(double a, double b, double c);  // "a b c", each tenSignificantDigits

tinyxml2::XMLElement* add(tinyxml2::XMLDocument& doc, tinyxml2::XMLElement* parent,
                          const char* tag);
// The <mujoco> root's child `tag` (<asset>, <custom>), made if there is none yet.
tinyxml2::XMLElement* section(tinyxml2::XMLDocument& doc, const char* tag);

Eigen::Vector3d vec(const urdf::Vector3& v);
Eigen::Quaterniond quat(const urdf::Rotation& r);
Eigen::Isometry3d pose(const urdf::Pose& p);
void setPose(tinyxml2::XMLElement* e, const urdf::Pose& p);  // its pos and (normalised) quat

}  // namespace cosim::urdf_mjcf
