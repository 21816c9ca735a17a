#pragma once
// Shared by the URDF fuzz targets: the converter reads the robot from a file, so the text is
// written to a per-process temporary file and converted there as a ground robot. Only
// cosim::InputError may reject it (see fuzz_input.h).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.h"
#include "sim/urdf_vehicle.h"

namespace cosim::fuzz {

inline void convertUrdfText(const std::string& urdf, const std::string& file_tag) {
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("cosim-fuzz-" + file_tag + "-" + std::to_string(::getpid()) + ".urdf");
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(urdf.data(), static_cast<std::streamsize>(urdf.size()));
  }
  tinyxml2::XMLDocument doc;
  tinyxml2::XMLElement* root = doc.NewElement("mujoco");
  doc.InsertEndChild(root);
  tinyxml2::XMLElement* worldbody = root->InsertNewChildElement("worldbody");
  VehicleSpec vehicle;
  vehicle.name = "robot";
  vehicle.model = file.string();
  vehicle.model_file = file;
  vehicle.kind = VehicleKind::GroundRobot;
  vehicle.waypoints.push_back({1.0, 1.0, 0.0});
  try {
    addUrdfVehicle(doc, worldbody, vehicle, 0.0);
    tinyxml2::XMLPrinter printer;
    doc.Print(&printer);
  } catch (const InputError&) {
  }
}

}  // namespace cosim::fuzz
