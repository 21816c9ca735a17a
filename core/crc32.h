#pragma once
// CRC-32 as zlib, PNG and MCAP use it (ISO-HDLC: reflected polynomial 0xEDB88320, initial value
// and final XOR 0xFFFFFFFF; CRC of "123456789" = 0xCBF43926).
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace cosim {

// Continues a CRC over more bytes: crc32(b, crc32(a)) == crc32(a + b). Start with 0.
std::uint32_t crc32(const void* data, std::size_t size, std::uint32_t crc = 0);
inline std::uint32_t crc32(std::string_view bytes, std::uint32_t crc = 0) {
  return crc32(bytes.data(), bytes.size(), crc);
}

}  // namespace cosim
