// libFuzzer target: the MovingAI .map reader (cosim::parseMovingAIMap).
#include "planning/grid/movingai.h"
#include "core/input_error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const cosim::OccupancyGrid grid =
        cosim::parseMovingAIMap(cosim::fuzz::text(data, size), "fuzz.map");
    // Touch every cell: the grid's size must match what it claims.
    long free_cells = 0;
    for (int y = 0; y < grid.ny(); ++y)
      for (int x = 0; x < grid.nx(); ++x) free_cells += grid.blocked({x, y, 0}) ? 0 : 1;
    if (free_cells < 0) __builtin_trap();
  } catch (const cosim::InputError&) {
  }
  return 0;
}
