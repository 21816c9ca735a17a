#include "experiments/identify/identification_log.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "core/csv_text.h"
#include "core/input_error.h"
#include "core/input_file.h"
#include "experiments/compare/usd_log_reader.h"

namespace cosim {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kRpm = 2.0 * std::numbers::pi / 60.0;
// Standard gravity (BIPM), the Crazyflie's accelerometer unit and the thrust stand's gram-force.
constexpr double kStandardGravity = 9.80665;

struct Unit {
  const char* name;
  double scale;  // to SI
};

struct Quantity {
  const char* column;
  std::vector<Unit> units;  // the first is the default
};

const std::vector<Quantity>& quantities() {
  static const std::vector<Quantity> q = [] {
    std::vector<Quantity> out;
    const std::vector<Unit> none{{"", 1.0}};
    const std::vector<Unit> rate{{"rad/s", 1.0}, {"deg/s", kDeg}};
    const std::vector<Unit> speed{{"rad/s", 1.0}, {"rpm", kRpm}};
    const std::vector<Unit> accel{{"m/s^2", 1.0}, {"g", kStandardGravity}};
    const std::vector<Unit> velocity{{"m/s", 1.0}};
    const std::vector<Unit> angle{{"rad", 1.0}, {"deg", kDeg}};
    out.push_back({"t", {{"s", 1.0}, {"ms", 1e-3}, {"us", 1e-6}}});
    out.push_back({"vbat", {{"V", 1.0}, {"mV", 1e-3}}});
    out.push_back({"thrust", {{"N", 1.0}, {"g", 1e-3 * kStandardGravity}}});
    for (const char* c : {"pwm", "pwm1", "pwm2", "pwm3", "pwm4", "qw", "qx", "qy", "qz"})
      out.push_back({c, none});
    for (const char* c : {"omega1", "omega2", "omega3", "omega4"}) out.push_back({c, speed});
    for (const char* c : {"rpm1", "rpm2", "rpm3", "rpm4"}) out.push_back({c, {{"rpm", kRpm}}});
    for (const char* c : {"gyro_x", "gyro_y", "gyro_z"}) out.push_back({c, rate});
    for (const char* c : {"acc_x", "acc_y", "acc_z"}) out.push_back({c, accel});
    for (const char* c : {"vx", "vy", "vz", "payload_vx", "payload_vy", "payload_vz"})
      out.push_back({c, velocity});
    for (const char* c : {"roll", "pitch", "roll_des", "pitch_des"}) out.push_back({c, angle});
    return out;
  }();
  return q;
}

// "name[unit]" -> its column and scale; false for a column cosim does not use.
bool knownColumn(const std::string& header, std::string& column, double& scale,
                 const std::string& file) {
  std::string name = header, unit;
  if (const auto open = header.find('['); open != std::string::npos && header.back() == ']') {
    name = header.substr(0, open);
    unit = header.substr(open + 1, header.size() - open - 2);
  }
  while (!name.empty() && name.front() == ' ') name.erase(name.begin());
  for (const auto& q : quantities()) {
    if (name != q.column) continue;
    for (const auto& u : q.units)
      if (unit.empty() || unit == u.name) {
        // rpm1..4 are omega1..4 read in rpm.
        column = name.rfind("rpm", 0) == 0 ? "omega" + name.substr(3) : name;
        scale = unit.empty() ? q.units.front().scale : u.scale;
        return true;
      }
    std::string known;
    for (const auto& u : q.units) known += std::string(known.empty() ? "" : ", ") + u.name;
    throw InputError(file, "line 1, column " + header,
                     "unknown unit '" + unit + "' for " + name + " (known: " + known + ")");
  }
  return false;
}

double finiteNumber(const std::string& s, const std::string& file, std::size_t line,
                    const std::string& column) {
  const char* begin = s.c_str();
  while (*begin == ' ') ++begin;
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  while (end && *end == ' ') ++end;
  if (*begin == '\0' || *end != '\0' || !std::isfinite(v))
    throw InputError(file, "line " + std::to_string(line) + ", column " + column,
                     "not a finite number: '" + s + "'");
  return v;
}

void checkTimes(const IdentificationLog& log, const std::string& where_prefix) {
  for (std::size_t i = 1; i < log.t.size(); ++i)
    if (!(log.t[i] > log.t[i - 1]))
      throw InputError(log.file, where_prefix + std::to_string(i + 1), "time does not increase");
}

// A CSV's `pwm` is every motor's.
void spreadSharedPwm(IdentificationLog& log) {
  const auto it = log.columns.find("pwm");
  if (it == log.columns.end()) return;
  for (const char* c : {"pwm1", "pwm2", "pwm3", "pwm4"})
    if (!log.has(c)) log.columns[c] = it->second;
  log.columns.erase("pwm");
}

}  // namespace

bool IdentificationLog::hasAll(const std::vector<std::string>& names) const {
  return std::all_of(names.begin(), names.end(), [&](const auto& n) { return has(n); });
}

double IdentificationLog::samplePeriod() const {
  if (t.size() < 2) return 0.0;
  std::vector<double> dt(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i) dt[i - 1] = t[i] - t[i - 1];
  std::nth_element(dt.begin(), dt.begin() + dt.size() / 2, dt.end());
  return dt[dt.size() / 2];
}

IdentificationLog parseIdentificationCsv(const std::string& text, const std::string& file) {
  IdentificationLog log;
  log.file = file;
  log.format = "csv";
  TextLines lines(text);
  std::string line;
  std::vector<std::string> names;
  if (!lines.next(line) || line.empty() || !splitCsvRecord(line, names))
    throw InputError(file, "line 1", "expected a CSV header naming the columns");
  struct Read {
    std::size_t field;
    std::string column;
    double scale;
  };
  std::vector<Read> reads;
  for (std::size_t i = 0; i < names.size(); ++i) {
    Read r{i, "", 1.0};
    if (!knownColumn(names[i], r.column, r.scale, file)) continue;
    for (const auto& other : reads)
      if (other.column == r.column)
        throw InputError(file, "line 1, column " + names[i], "column " + r.column + " twice");
    reads.push_back(r);
  }
  if (reads.empty())
    throw InputError(file, "line 1",
                     "no column cosim identify uses (t, vbat, pwm1..4, rpm1..4, thrust, gyro_x, "
                     "acc_x, vx, qw, ...: see docs/identify.md)");
  std::vector<std::string> row;
  while (lines.next(line)) {
    if (line.empty()) continue;
    if (!splitCsvRecord(line, row) || row.size() != names.size())
      throw InputError(file, "line " + std::to_string(lines.number()),
                       "has " + std::to_string(row.size()) + " fields, the header has " +
                           std::to_string(names.size()));
    for (const auto& r : reads) {
      const double v = r.scale * finiteNumber(row[r.field], file, lines.number(), names[r.field]);
      if (r.column == "t")
        log.t.push_back(v);
      else
        log.columns[r.column].push_back(v);
    }
    ++log.rows;
  }
  if (log.rows < 3)
    throw InputError(file, "line " + std::to_string(lines.number()), "too few rows");
  checkTimes(log, "line ");
  spreadSharedPwm(log);
  return log;
}

IdentificationLog parseIdentificationUsd(std::string bytes, const std::string& file) {
  const UsdLog usd = UsdLog::parse(std::move(bytes), file);
  struct Var {
    const char* usd;
    const char* column;
    double scale;
  };
  // The firmware's log variables and their units: rpm deck in rpm, gyro in deg/s, accelerometer
  // in g, pm.vbatMV in mV; stateEstimateZ is the compressed state, millimetres (per second).
  static const std::vector<Var> vars{{"pm.vbatMV", "vbat", 1e-3},
                                     {"pm.vbat", "vbat", 1.0},
                                     {"pwm.m1_pwm", "pwm1", 1.0},
                                     {"pwm.m2_pwm", "pwm2", 1.0},
                                     {"pwm.m3_pwm", "pwm3", 1.0},
                                     {"pwm.m4_pwm", "pwm4", 1.0},
                                     {"rpm.m1", "omega1", kRpm},
                                     {"rpm.m2", "omega2", kRpm},
                                     {"rpm.m3", "omega3", kRpm},
                                     {"rpm.m4", "omega4", kRpm},
                                     {"gyro.x", "gyro_x", kDeg},
                                     {"gyro.y", "gyro_y", kDeg},
                                     {"gyro.z", "gyro_z", kDeg},
                                     {"acc.x", "acc_x", kStandardGravity},
                                     {"acc.y", "acc_y", kStandardGravity},
                                     {"acc.z", "acc_z", kStandardGravity},
                                     {"stateEstimate.vx", "vx", 1.0},
                                     {"stateEstimate.vy", "vy", 1.0},
                                     {"stateEstimate.vz", "vz", 1.0},
                                     {"stateEstimate.qw", "qw", 1.0},
                                     {"stateEstimate.qx", "qx", 1.0},
                                     {"stateEstimate.qy", "qy", 1.0},
                                     {"stateEstimate.qz", "qz", 1.0},
                                     {"stateEstimateZ.pvx", "payload_vx", 1e-3},
                                     {"stateEstimateZ.pvy", "payload_vy", 1e-3},
                                     {"stateEstimateZ.pvz", "payload_vz", 1e-3},
                                     {"ctrlLee.rpyx", "roll", 1.0},
                                     {"ctrlLee.rpyy", "pitch", 1.0},
                                     {"ctrlLee.rpydx", "roll_des", 1.0},
                                     {"ctrlLee.rpydy", "pitch_des", 1.0}};
  // The event type holding the most of them (the fixed-frequency one, as the firmware logs).
  std::size_t best = 0, best_count = 0;
  for (std::size_t i = 0; i < usd.eventTypes().size(); ++i) {
    std::size_t count = 0;
    for (const auto& var : usd.eventTypes()[i].variables)
      for (const auto& v : vars) count += var.name == v.usd ? 1 : 0;
    if (count > best_count) best = i, best_count = count;
  }
  if (best_count == 0)
    throw InputError(file, "header",
                     "no event holds a variable cosim identify uses (pwm.m1_pwm, rpm.m1, "
                     "pm.vbatMV, gyro.x, acc.x, stateEstimate.vx, ...)");
  std::vector<std::string> names;
  std::vector<const Var*> used;
  for (const auto& var : usd.eventTypes()[best].variables)
    for (const auto& v : vars)
      if (var.name == v.usd) {
        names.push_back(v.usd);
        used.push_back(&v);
      }
  const UsdSeries s = usd.series(best, names);
  IdentificationLog log;
  log.file = file;
  log.format = "Crazyflie uSD log version " + std::to_string(usd.version());
  log.t = s.t;
  log.rows = s.t.size();
  for (std::size_t i = 0; i < used.size(); ++i) {
    auto& column = log.columns[used[i]->column];
    column.resize(log.rows);
    for (std::size_t k = 0; k < log.rows; ++k) column[k] = used[i]->scale * s.values[i][k];
  }
  if (log.rows < 3) throw InputError(file, "records", "too few records");
  checkTimes(log, "record ");
  return log;
}

IdentificationLog readIdentificationLog(const std::string& path) {
  std::string bytes = readInputFile(path, kMaxLogFileBytes, "identification log");
  if (looksLikeUsdLog(bytes)) return parseIdentificationUsd(std::move(bytes), path);
  return parseIdentificationCsv(bytes, path);
}

}  // namespace cosim
