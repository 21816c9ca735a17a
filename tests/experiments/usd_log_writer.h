#pragma once
// Writes Crazyflie uSD-card logs for tests, byte by byte from the format's description (header
// of typed variables, timestamped records, CRC-32 at the end), so that the reader is checked
// against files made independently of it.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "core/crc32.h"

namespace cosim::test {

class UsdLogWriter {
 public:
  explicit UsdLogWriter(int version) : version_(version) {}

  struct Type {
    std::uint16_t id;
    std::string name;
    std::vector<std::string> variables;  // "group.name(t)"
  };
  void addType(const Type& t) { types_.push_back(t); }

  // A record: event id, time in seconds, then the value bytes (see put* below).
  void record(std::uint16_t id, double t_s, const std::string& values) {
    putInt(records_, id, 2);
    if (version_ == 1)
      putInt(records_, static_cast<std::uint64_t>(t_s * 1e3 + 0.5), 4);
    else
      putInt(records_, static_cast<std::uint64_t>(t_s * 1e6 + 0.5), 8);
    records_ += values;
  }

  // The whole file; `damage` flips a bit of the CRC.
  std::string bytes(bool damage = false) const {
    std::string b(1, static_cast<char>(0xBC));
    putInt(b, static_cast<std::uint64_t>(version_), 2);
    putInt(b, types_.size(), 2);
    for (const Type& t : types_) {
      putInt(b, t.id, 2);
      b += t.name;
      b += '\0';
      putInt(b, t.variables.size(), 2);
      for (const auto& v : t.variables) {
        b += v;
        b += '\0';
      }
    }
    b += records_;
    std::uint32_t crc = crc32(reinterpret_cast<const unsigned char*>(b.data()), b.size());
    if (damage) crc ^= 1u;
    putInt(b, crc, 4);
    return b;
  }

  static void putInt(std::string& b, std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) b += static_cast<char>((v >> (8 * i)) & 0xFF);
  }
  static std::string f32(float v) {
    std::uint32_t r;
    std::memcpy(&r, &v, 4);
    std::string b;
    putInt(b, r, 4);
    return b;
  }
  static std::string f64(double v) {
    std::uint64_t r;
    std::memcpy(&r, &v, 8);
    std::string b;
    putInt(b, r, 8);
    return b;
  }
  static std::string integer(std::int64_t v, int n) {
    std::string b;
    putInt(b, static_cast<std::uint64_t>(v), n);
    return b;
  }

 private:
  int version_;
  std::vector<Type> types_;
  std::string records_;
};

}  // namespace cosim::test
