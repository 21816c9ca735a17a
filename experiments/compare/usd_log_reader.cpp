#include "experiments/compare/usd_log_reader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "core/crc32.h"
#include "core/input_error.h"

namespace cosim {

namespace {

constexpr unsigned char kMagic = 0xBC;
constexpr std::size_t kCrcBytes = 4;

std::string byteAt(std::size_t at) {
  return "byte " + std::to_string(at);
}

std::uint64_t littleEndian(const std::string& b, std::size_t at, std::size_t n) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < n; ++i)
    v |= static_cast<std::uint64_t>(static_cast<unsigned char>(b[at + i])) << (8 * i);
  return v;
}

// Bytes of one value of a struct type letter (Python's struct module, standard sizes with '<');
// 0 for a letter the format does not have.
std::size_t typeSize(char t) {
  switch (t) {
    case 'b':
    case 'B':
    case '?':
    case 'c':
      return 1;
    case 'h':
    case 'H':
    case 'e':
      return 2;
    case 'i':
    case 'I':
    case 'l':
    case 'L':
    case 'f':
      return 4;
    case 'q':
    case 'Q':
    case 'd':
      return 8;
    default:
      return 0;
  }
}

// IEEE 754 half precision (1 sign, 5 exponent bits of bias 15, 10 fraction bits).
double halfToDouble(std::uint16_t h) {
  const int sign = (h >> 15) ? -1 : 1, exponent = (h >> 10) & 0x1F, fraction = h & 0x3FF;
  if (exponent == 0) return sign * std::ldexp(fraction, -24);  // subnormal: fraction * 2^-24
  if (exponent == 31) return fraction ? std::nan("") : sign * HUGE_VAL;
  return sign * std::ldexp(1024 + fraction, exponent - 25);
}

double decodeValue(const std::string& b, std::size_t at, char t) {
  const std::uint64_t raw = littleEndian(b, at, typeSize(t));
  switch (t) {
    case 'b':
      return static_cast<std::int8_t>(raw);
    case 'h':
      return static_cast<std::int16_t>(raw);
    case 'i':
    case 'l':
      return static_cast<std::int32_t>(raw);
    case 'q':
      return static_cast<double>(static_cast<std::int64_t>(raw));
    case 'e':
      return halfToDouble(static_cast<std::uint16_t>(raw));
    case 'f': {
      const std::uint32_t r32 = static_cast<std::uint32_t>(raw);
      float f;
      std::memcpy(&f, &r32, sizeof f);
      return f;
    }
    case 'd': {
      double d;
      std::memcpy(&d, &raw, sizeof d);
      return d;
    }
    default:
      return static_cast<double>(raw);  // unsigned and 1-byte types
  }
}

}  // namespace

bool looksLikeUsdLog(const std::string& bytes) {
  return !bytes.empty() && static_cast<unsigned char>(bytes[0]) == kMagic;
}

UsdLog UsdLog::parse(std::string bytes, const std::string& file) {
  UsdLog log;
  log.bytes_ = std::move(bytes);
  log.file_ = file;
  const std::string& b = log.bytes_;
  if (b.size() < 1 + 2 + 2 + kCrcBytes)
    throw InputError(file, byteAt(b.size()),
                     "too short for a Crazyflie uSD log (" + std::to_string(b.size()) + " bytes)");
  if (!looksLikeUsdLog(b))
    throw InputError(file, byteAt(0), "not a Crazyflie uSD log (first byte is not 0xBC)");
  // The CRC first: a file cut short or damaged says so, not some symptom of it further on.
  log.records_end_ = b.size() - kCrcBytes;
  const auto stored = static_cast<std::uint32_t>(littleEndian(b, log.records_end_, kCrcBytes));
  const std::uint32_t computed =
      crc32(reinterpret_cast<const unsigned char*>(b.data()), log.records_end_);
  if (stored != computed) {
    char msg[160];
    std::snprintf(msg, sizeof msg,
                  "CRC-32 mismatch: the file ends with 0x%08X, its content gives 0x%08X "
                  "(truncated or damaged log)",
                  stored, computed);
    throw InputError(file, byteAt(log.records_end_), msg);
  }
  log.version_ = static_cast<int>(littleEndian(b, 1, 2));
  if (log.version_ != 1 && log.version_ != 2)
    throw InputError(
        file, byteAt(1),
        "unsupported uSD log version " + std::to_string(log.version_) + " (1 and 2 are known)");
  log.records_begin_ = log.readHeader();
  log.checkRecords();
  return log;
}

std::size_t UsdLog::readHeader() {
  const std::string& b = bytes_;
  const std::size_t end = records_end_;
  const std::size_t count = littleEndian(b, 3, 2);
  std::size_t at = 5;
  const auto need = [&](std::size_t n, const char* what) {
    if (at + n > end)
      throw InputError(file_, byteAt(at), std::string("header ends inside ") + what);
  };
  const auto text = [&](const char* what) {
    const std::size_t stop = b.find('\0', at);
    if (stop == std::string::npos || stop >= end)
      throw InputError(file_, byteAt(at), std::string("header ends inside ") + what);
    std::string s = b.substr(at, stop - at);
    at = stop + 1;
    return s;
  };
  for (std::size_t k = 0; k < count; ++k) {
    UsdEventType type;
    need(2, "an event id");
    type.id = static_cast<std::uint16_t>(littleEndian(b, at, 2));
    if (!type_of_id_.emplace(type.id, types_.size()).second)
      throw InputError(file_, byteAt(at), "event id " + std::to_string(type.id) + " twice");
    at += 2;
    type.name = text("an event name");
    need(2, "a variable count");
    const std::size_t variables = littleEndian(b, at, 2);
    at += 2;
    for (std::size_t v = 0; v < variables; ++v) {
      const std::size_t start = at;
      const std::string spec = text("a variable name");
      // "name(t)": a name, then one type letter in parentheses.
      if (spec.size() < 4 || spec[spec.size() - 3] != '(' || spec.back() != ')')
        throw InputError(file_, byteAt(start),
                         "variable '" + spec + "' is not of the form name(t)");
      UsdVariable var{spec.substr(0, spec.size() - 3), spec[spec.size() - 2], type.value_bytes};
      if (typeSize(var.type) == 0)
        throw InputError(
            file_, byteAt(start + spec.size() - 2),
            "unknown type letter '" + std::string(1, var.type) + "' of variable " + var.name);
      type.value_bytes += typeSize(var.type);
      type.variables.push_back(std::move(var));
    }
    types_.push_back(std::move(type));
  }
  return at;
}

std::size_t UsdLog::typeIndex(std::uint16_t id, std::size_t at) const {
  const auto it = type_of_id_.find(id);
  if (it != type_of_id_.end()) return it->second;
  throw InputError(
      file_, byteAt(at),
      "record of event id " + std::to_string(id) + ", which the header does not declare");
}

void UsdLog::checkRecords() {
  const std::size_t stamp = version_ == 1 ? 4 : 8;
  for (std::size_t at = records_begin_; at < records_end_;) {
    if (at + 2 + stamp > records_end_)
      throw InputError(file_, byteAt(at), "truncated record (the file ends inside its header)");
    UsdEventType& type =
        types_[typeIndex(static_cast<std::uint16_t>(littleEndian(bytes_, at, 2)), at)];
    const std::size_t next = at + 2 + stamp + type.value_bytes;
    if (next > records_end_)
      throw InputError(file_, byteAt(at),
                       "truncated record of event " + type.name + " (needs " +
                           std::to_string(2 + stamp + type.value_bytes) + " bytes, " +
                           std::to_string(records_end_ - at) + " left)");
    ++type.records;
    at = next;
  }
}

int UsdLog::typeWithVariables(const std::vector<std::string>& names) const {
  for (std::size_t i = 0; i < types_.size(); ++i) {
    const auto has = [&](const std::string& n) {
      return std::any_of(types_[i].variables.begin(), types_[i].variables.end(),
                         [&](const UsdVariable& v) { return v.name == n; });
    };
    if (std::all_of(names.begin(), names.end(), has)) return static_cast<int>(i);
  }
  return -1;
}

UsdSeries UsdLog::series(std::size_t type, const std::vector<std::string>& names) const {
  const UsdEventType& wanted = types_.at(type);
  std::vector<const UsdVariable*> vars;
  for (const std::string& n : names) {
    const auto it = std::find_if(wanted.variables.begin(), wanted.variables.end(),
                                 [&](const UsdVariable& v) { return v.name == n; });
    if (it == wanted.variables.end())
      throw std::invalid_argument("event " + wanted.name + " has no variable " + n);
    vars.push_back(&*it);
  }
  UsdSeries s;
  s.values.assign(names.size(), {});
  const std::size_t stamp = version_ == 1 ? 4 : 8;
  // Version 1 stamps milliseconds, version 2 microseconds.
  const double seconds_per_tick = version_ == 1 ? 1e-3 : 1e-6;
  for (std::size_t at = records_begin_; at < records_end_;) {
    const UsdEventType& t =
        types_[typeIndex(static_cast<std::uint16_t>(littleEndian(bytes_, at, 2)), at)];
    if (t.id == wanted.id) {
      s.t.push_back(static_cast<double>(littleEndian(bytes_, at + 2, stamp)) * seconds_per_tick);
      s.record_byte.push_back(at);
      for (std::size_t i = 0; i < vars.size(); ++i)
        s.values[i].push_back(decodeValue(bytes_, at + 2 + stamp + vars[i]->offset, vars[i]->type));
    }
    at += 2 + stamp + t.value_bytes;
  }
  return s;
}

}  // namespace cosim
