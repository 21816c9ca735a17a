// libFuzzer target: the URDF-to-MuJoCo conversion (cosim::addUrdfVehicle). The converter reads
// the robot from a file, so each input is written to a per-process temporary file first.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "planning/input_error.h"
#include "sim/urdf_vehicle.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                            ("cosim-fuzz-" + std::to_string(::getpid()) + ".urdf");
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  tinyxml2::XMLDocument doc;
  tinyxml2::XMLElement* root = doc.NewElement("mujoco");
  doc.InsertEndChild(root);
  tinyxml2::XMLElement* worldbody = root->InsertNewChildElement("worldbody");
  cosim::VehicleSpec vehicle;
  vehicle.name = "robot";
  vehicle.model = file.string();
  vehicle.model_file = file;
  vehicle.ground = true;
  vehicle.waypoints.push_back({1.0, 1.0, 0.0});
  try {
    cosim::addUrdfVehicle(doc, worldbody, vehicle, 0.0);
    tinyxml2::XMLPrinter printer;
    doc.Print(&printer);
  } catch (const cosim::InputError&) {
  }
  return 0;
}
