// libFuzzer target: the CSV flight log reader of cosim compare-real (cosim::parseFlightLogCsv).
#include "core/input_error.h"
#include "experiments/compare/flight_log.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const cosim::FlightLog log =
        cosim::parseFlightLogCsv(cosim::fuzz::text(data, size), "fuzz.csv");
    // Reading between the samples must stay inside the data.
    log.position.at(0.5 * (log.position.start() + log.position.end()));
  } catch (const cosim::InputError&) {
  }
  return 0;
}
