#pragma once
// Base64 (RFC 4648, section 4: the standard alphabet with '=' padding), for binary data embedded
// in text files such as a run's viewer.html.
#include <cstdint>
#include <string>
#include <vector>

namespace cosim {

std::string base64Encode(const std::uint8_t* data, std::size_t size);
inline std::string base64Encode(const std::vector<std::uint8_t>& data) {
  return base64Encode(data.data(), data.size());
}

}  // namespace cosim
