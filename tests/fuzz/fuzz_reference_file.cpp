// libFuzzer target: the reference file reader (cosim::parseReferenceText), both formats.
#include <cmath>

#include "control/reference_file.h"
#include "core/input_error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const cosim::ReferenceFile file =
        cosim::parseReferenceText(cosim::fuzz::text(data, size), "fuzz.csv");
    // Evaluate it before, inside and after its duration, placed at half speed: the reader's
    // limits (values within 1e9, intervals of at least 1e-6 s) keep every output finite.
    const cosim::PiecewisePolynomialReference placed = file.reference.placed({0.5, {1, 2, 3}});
    const double T = placed.duration();
    for (const double t : {-1.0, 0.0, 0.37 * T, 0.5 * T, T, T + 1.0}) {
      const cosim::FlatReference r = placed.at(t);
      if (!r.position.allFinite() || !r.snap.allFinite() || !std::isfinite(r.yaw_acceleration))
        __builtin_trap();
    }
    if (placed.sampledPath(50, 0.01).size() < 2) __builtin_trap();
  } catch (const cosim::InputError&) {
  }
  return 0;
}
