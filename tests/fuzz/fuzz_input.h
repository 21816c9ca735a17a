#pragma once
// Shared by the libFuzzer targets: a parser under test may reject an input only with
// cosim::InputError (which the program turns into one stderr line and exit 2). Any other
// exception escaping, a crash, a sanitizer report, a leak or a hang is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

namespace cosim::fuzz {

inline std::string text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace cosim::fuzz
