// libFuzzer target: the URDF-to-MuJoCo conversion (cosim::addUrdfVehicle) on URDF text as it
// comes.
#include "tests/fuzz/fuzz_input.h"
#include "tests/fuzz/urdf_conversion.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cosim::fuzz::convertUrdfText(cosim::fuzz::text(data, size), "urdf");
  return 0;
}
