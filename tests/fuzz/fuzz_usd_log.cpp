// libFuzzer target: the Crazyflie uSD-card log reader of cosim compare-real
// (cosim::parseFlightLogUsd over cosim::UsdLog). The CRC closes every valid log, so a mutated
// input almost always fails it: the target also reads each input with its last four bytes
// replaced by the right CRC, which lets the mutations reach the header and the records.
#include <string>

#include "core/crc32.h"
#include "core/input_error.h"
#include "experiments/compare/flight_log.h"
#include "tests/fuzz/fuzz_input.h"

namespace {

void read(std::string bytes) {
  try {
    const cosim::FlightLog log = cosim::parseFlightLogUsd(std::move(bytes), "fuzz.bin");
    log.position.at(0.5 * (log.position.start() + log.position.end()));
  } catch (const cosim::InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes = cosim::fuzz::text(data, size);
  read(bytes);
  if (bytes.size() >= 4) {
    const std::uint32_t crc =
        cosim::crc32(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size() - 4);
    for (int i = 0; i < 4; ++i)
      bytes[bytes.size() - 4 + i] = static_cast<char>((crc >> (8 * i)) & 0xFF);
    read(std::move(bytes));
  }
  return 0;
}
