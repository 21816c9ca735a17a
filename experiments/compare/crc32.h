#pragma once
// The CRC-32 that closes a Crazyflie uSD-card log: the IEEE 802.3 / zlib CRC (reflected
// polynomial 0xEDB88320, initial value and final XOR 0xFFFFFFFF), the one Python's zlib.crc32
// computes and the firmware's usddeck writes over every byte before the last four.
#include <cstddef>
#include <cstdint>

namespace cosim {

std::uint32_t crc32(const unsigned char* data, std::size_t size);

}  // namespace cosim
