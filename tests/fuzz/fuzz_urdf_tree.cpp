// libFuzzer target: the URDF converter (cosim::addUrdfVehicle) on robots of every tree shape,
// grown from the input bytes rather than found by mutating XML text (which almost never makes a
// deep tree). Byte i describes link i + 1: its parent is one of the four links before it
// (`byte & 3` back: all zeros make a chain as long as the input), its joint type is
// `(byte >> 2) & 3` (fixed, revolute, continuous, prismatic) and bit 4 gives it a collision box.
// A 20 000-byte input is the 20 000-link chain whose recursive conversion crashed the program.
#include <string>

#include "tests/fuzz/fuzz_input.h"
#include "tests/fuzz/urdf_conversion.h"

namespace {

std::string treeUrdf(const std::uint8_t* data, std::size_t size) {
  static const char* const kJointTypes[] = {"fixed", "revolute", "continuous", "prismatic"};
  const std::string inertial =
      "<inertial><mass value=\"1\"/><inertia ixx=\"0.01\" iyy=\"0.01\" izz=\"0.01\" ixy=\"0\" "
      "ixz=\"0\" iyz=\"0\"/></inertial>";
  const std::string box = "<collision><geometry><box size=\"0.1 0.1 0.1\"/></geometry></collision>";
  std::string u = "<robot name=\"tree\">\n<link name=\"l0\">" + inertial + box + "</link>\n";
  for (std::size_t i = 0; i < size; ++i) {
    const std::size_t link = i + 1;
    const std::size_t back = 1 + (data[i] & 3u);
    const std::size_t parent = link > back ? link - back : 0;
    const char* type = kJointTypes[(data[i] >> 2) & 3u];
    const std::string name = std::to_string(link);
    u += "<link name=\"l" + name + "\">" + inertial + ((data[i] & 16u) ? box : "") + "</link>\n";
    u += "<joint name=\"j" + name + "\" type=\"" + type + "\"><parent link=\"l" +
         std::to_string(parent) + "\"/><child link=\"l" + name +
         "\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>"
         "</joint>\n";
  }
  return u + "</robot>\n";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cosim::fuzz::convertUrdfText(treeUrdf(data, size), "tree");
  return 0;
}
