#pragma once
// Reading a ground robot's URDF file for the conversion (sim/urdf_vehicle.h): checked as XML
// first (errors with a line number), refused if it is far larger than any robot or its joints
// do not make a tree, then parsed by urdfdom with its complaint turned into the InputError.
#include <urdf_world/types.h>

#include <filesystem>
#include <string>

namespace cosim {

// Throws InputError naming `file` (and the line or element) for an unreadable, malformed or
// oversized URDF.
urdf::ModelInterfaceSharedPtr parseUrdf(const std::string& file);

// Where a URDF's <mesh filename> points: file:// stripped, relative to the URDF's folder `dir`;
// empty for package:// (which needs ROS).
std::filesystem::path meshPath(const std::string& filename, const std::filesystem::path& dir);

}  // namespace cosim
