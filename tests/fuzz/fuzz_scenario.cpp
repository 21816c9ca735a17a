// libFuzzer target: the scenario YAML loader (cosim::parseScenario), as `cosim run` and
// `cosim plan` call it on a user's file.
#include "core/input_error.h"
#include "sim/scenario.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    // A path inside the source tree so relative model/include paths resolve as for a bundled
    // scenario.
    cosim::parseScenario(cosim::fuzz::text(data, size),
                         COSIM_SOURCE_DIR "/experiments/scenarios/fuzz.yaml");
  } catch (const cosim::InputError&) {
  }
  return 0;
}
