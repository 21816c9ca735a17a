// libFuzzer target: the sweep file loader (cosim::parseSweepSpec), as `cosim sweep` calls it.
#include "experiments/sweep/sweep_spec.h"
#include "core/input_error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    cosim::parseSweepSpec(cosim::fuzz::text(data, size),
                          COSIM_SOURCE_DIR "/experiments/sweeps/fuzz.yaml");
  } catch (const cosim::InputError&) {
  }
  return 0;
}
