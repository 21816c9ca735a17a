#pragma once
// The Crazyflie uSD-card binary event log, as the firmware's usddeck writes it and its Python
// decoder (tools/usdlog/cfusdlog.py) reads it. All numbers little-endian:
//   byte 0xBC, uint16 version (1 or 2), uint16 number of event types;
//   per event type: uint16 id, its name (NUL-terminated), uint16 number of variables, and per
//   variable "group.name(t)" (NUL-terminated; t a Python struct type letter: b B h H i I l L
//   q Q f d e ? c);
//   then records: uint16 event id, the time (version 1: uint32 milliseconds; version 2: uint64
//   microseconds), then the event's variables packed in header order;
//   the last 4 bytes: CRC-32 of every byte before them (core/crc32.h).
// Reading checks all of it: a wrong CRC, a truncated record, an unknown event id or type
// letter is an InputError naming the file and the byte.
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace cosim {

struct UsdVariable {
  std::string name;        // "group.name", e.g. "locSrv.x"
  char type = 'f';         // struct type letter
  std::size_t offset = 0;  // bytes from the start of the record's values
};

struct UsdEventType {
  std::uint16_t id = 0;
  std::string name;  // e.g. "fixedFrequency"
  std::vector<UsdVariable> variables;
  std::size_t value_bytes = 0;  // packed size of the variables
  std::size_t records = 0;      // how many records the log holds
};

// Some variables of one event type over time, in record order.
struct UsdSeries {
  std::vector<double> t;                    // s (the firmware's clock)
  std::vector<std::vector<double>> values;  // values[i][k]: variable i of record k
  std::vector<std::size_t> record_byte;     // where each record starts in the file
};

class UsdLog {
 public:
  // Parses and checks the whole log (header, every record, CRC). `file` names it in errors.
  static UsdLog parse(std::string bytes, const std::string& file);

  int version() const { return version_; }
  const std::vector<UsdEventType>& eventTypes() const { return types_; }
  // Index of the event type holding all of `names` (the first such), or -1.
  int typeWithVariables(const std::vector<std::string>& names) const;
  // The named variables of event type `type` (an index into eventTypes()); every name must be
  // one of its variables (std::invalid_argument otherwise).
  UsdSeries series(std::size_t type, const std::vector<std::string>& names) const;

 private:
  std::size_t readHeader();
  void checkRecords();
  std::size_t typeIndex(std::uint16_t id, std::size_t at) const;

  std::string bytes_, file_;
  int version_ = 0;
  std::vector<UsdEventType> types_;
  std::unordered_map<std::uint16_t, std::size_t> type_of_id_;
  std::size_t records_begin_ = 0, records_end_ = 0;
};

// Whether `bytes` begin like a uSD log (the magic byte 0xBC).
bool looksLikeUsdLog(const std::string& bytes);

}  // namespace cosim
