// libFuzzer target: the MovingAI .scen reader (cosim::parseMovingAIScenario).
#include "planning/grid/movingai.h"
#include "core/input_error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    for (const auto& line :
         cosim::parseMovingAIScenario(cosim::fuzz::text(data, size), "fuzz.scen"))
      cosim::matchesOptimalLength(line, line.optimal_length);
  } catch (const cosim::InputError&) {
  }
  return 0;
}
