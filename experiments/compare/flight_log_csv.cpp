// The CSV flight log: header t,x,y,z[,ref_x,ref_y,ref_z] (any order, other columns ignored).
#include <cmath>
#include <cstdlib>
#include <map>

#include "core/csv_text.h"
#include "core/input_error.h"
#include "experiments/compare/flight_log.h"

namespace cosim {

namespace {

struct Columns {
  std::size_t fields, t, x, y, z;
  bool ref = false;
  std::size_t rx = 0, ry = 0, rz = 0;
};

Columns headerColumns(const std::string& line, const std::string& file) {
  std::vector<std::string> names;
  if (line.empty() || !splitCsvRecord(line, names))
    throw InputError(file, "line 1",
                     "expected a CSV header t,x,y,z (optionally ref_x,ref_y,ref_z)");
  std::map<std::string, std::size_t> at;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (!at.emplace(names[i], i).second)
      throw InputError(file, "line 1", "column '" + names[i] + "' twice");
  for (const char* required : {"t", "x", "y", "z"})
    if (!at.count(required))
      throw InputError(file, "line 1",
                       std::string("missing column '") + required +
                           "' (the header must name t,x,y,z; seconds and metres)");
  Columns c{names.size(), at["t"], at["x"], at["y"], at["z"]};
  const int refs = static_cast<int>(at.count("ref_x") + at.count("ref_y") + at.count("ref_z"));
  if (refs != 0 && refs != 3)
    throw InputError(file, "line 1", "reference columns need all of ref_x,ref_y,ref_z");
  if (refs == 3) {
    c.ref = true;
    c.rx = at["ref_x"];
    c.ry = at["ref_y"];
    c.rz = at["ref_z"];
  }
  return c;
}

double finiteNumber(const std::vector<std::string>& row, std::size_t i, const std::string& file,
                    std::size_t line, const char* column) {
  const std::string& s = row[i];
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(v))
    throw InputError(file, "line " + std::to_string(line) + ", column " + column,
                     "not a finite number: '" + s + "'");
  return v;
}

double coordinate(const std::vector<std::string>& row, std::size_t i, const std::string& file,
                  std::size_t line, const char* column) {
  const double v = finiteNumber(row, i, file, line, column);
  if (std::abs(v) > kMaxFlightCoordinateM)
    throw InputError(file, "line " + std::to_string(line) + ", column " + column,
                     "'" + row[i] + "' m is further than 1e6 m from the origin: not a flight");
  return v;
}

}  // namespace

FlightLog parseFlightLogCsv(const std::string& text, const std::string& file) {
  FlightLog log;
  log.file = file;
  log.format = "csv";
  TextLines lines(text);
  std::string line;
  if (!lines.next(line)) throw InputError(file, "line 1", "empty file, expected a header t,x,y,z");
  const Columns c = headerColumns(line, file);
  log.position_source = "columns x,y,z";
  if (c.ref) log.reference_source = "columns ref_x,ref_y,ref_z";
  const std::size_t fields = c.fields;
  std::vector<std::string> row;
  while (lines.next(line)) {
    if (line.empty()) continue;
    if (!splitCsvRecord(line, row) || row.size() != fields)
      throw InputError(file, "line " + std::to_string(lines.number()),
                       "has " + std::to_string(row.size()) + " fields, the header has " +
                           std::to_string(fields));
    const double t = finiteNumber(row, c.t, file, lines.number(), "t");
    if (!log.position.t.empty() && t <= log.position.t.back())
      throw InputError(file, "line " + std::to_string(lines.number()) + ", column t",
                       "time does not increase (" + row[c.t] + " after the previous row)");
    log.position.t.push_back(t);
    log.position.p.emplace_back(coordinate(row, c.x, file, lines.number(), "x"),
                                coordinate(row, c.y, file, lines.number(), "y"),
                                coordinate(row, c.z, file, lines.number(), "z"));
    if (c.ref) {
      log.reference.t.push_back(t);
      log.reference.p.emplace_back(coordinate(row, c.rx, file, lines.number(), "ref_x"),
                                   coordinate(row, c.ry, file, lines.number(), "ref_y"),
                                   coordinate(row, c.rz, file, lines.number(), "ref_z"));
    }
  }
  if (log.position.size() < kMinFlightLogSamples)
    throw InputError(file, "line " + std::to_string(lines.number()),
                     "too few samples: " + std::to_string(log.position.size()) +
                         " rows, at least " + std::to_string(kMinFlightLogSamples) + " needed");
  return log;
}

}  // namespace cosim
