#include "sim/run_log_io.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "core/input_error.h"
#include "core/input_file.h"
#include "core/csv_text.h"

namespace cosim {

namespace {

// timeseries.csv's numeric columns, in order (the file adds `vehicle`, the name, last), and
// their values for one sample: the one definition behind timeseriesCsv and timeseriesColumns.
constexpr std::array<const char*, 46> kTimeseriesColumns = {
    "t",      "ref_x",    "ref_y",     "ref_z",   "ref_vx",  "ref_vy",  "ref_vz",  "x",
    "y",      "z",        "vx",        "vy",      "vz",      "qw",      "qx",      "qy",
    "qz",     "roll_deg", "pitch_deg", "yaw_deg", "p",       "q",       "r",       "cmd0",
    "cmd1",   "cmd2",     "cmd3",      "thrust0", "thrust1", "thrust2", "thrust3", "saturated",
    "est_x",  "est_y",    "est_z",     "est_vx",  "est_vy",  "est_vz",  "est_qw",  "est_qx",
    "est_qy", "est_qz",   "w0",        "w1",      "w2",      "w3"};
using TimeseriesRow = std::array<double, kTimeseriesColumns.size()>;

TimeseriesRow timeseriesRow(const LogSample& s) {
  TimeseriesRow row;
  std::size_t i = 0;
  const auto put3 = [&](const Eigen::Vector3d& v) {
    for (int k = 0; k < 3; ++k) row[i++] = v[k];
  };
  const auto put4 = [&](const Eigen::Vector4d& v) {
    for (int k = 0; k < 4; ++k) row[i++] = v[k];
  };
  const auto putQuaternion = [&](const Eigen::Quaterniond& q) {
    row[i++] = q.w();
    row[i++] = q.x();
    row[i++] = q.y();
    row[i++] = q.z();
  };
  row[i++] = s.t;
  put3(s.ref_pos);
  put3(s.ref_vel);
  put3(s.pos);
  put3(s.vel);
  putQuaternion(s.att);
  // Roll, pitch and yaw (Z-Y-X Euler angles) of the attitude, degrees.
  const Eigen::Matrix3d R = s.att.toRotationMatrix();
  row[i++] = std::atan2(R(2, 1), R(2, 2)) * 180.0 / M_PI;
  row[i++] = -std::asin(std::clamp(R(2, 0), -1.0, 1.0)) * 180.0 / M_PI;
  row[i++] = std::atan2(R(1, 0), R(0, 0)) * 180.0 / M_PI;
  put3(s.omega);
  put4(s.rotor_cmd);
  put4(s.rotor_thrust);
  row[i++] = s.saturated ? 1.0 : 0.0;
  put3(s.est_pos);
  put3(s.est_vel);
  putQuaternion(s.est_att);
  put4(s.rotor_speed);
  return row;
}

void put(std::string& out, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g,", v);
  out += buf;
}

// A run log read line by line, each line split into its fields by the header's column names.
// Never holds more than one line: a log of a gigabyte costs its samples, not its text.
class CsvLogReader {
 public:
  CsvLogReader(const std::string& path, const std::vector<std::string>& required) : path_(path) {
    checkInputFile(path, kMaxLogFileBytes, "run log");
    in_.open(path, std::ios::binary);
    if (!in_) throw InputError(path, "", "cannot open file");
    if (!nextLine()) throw InputError(path, "line 1", "empty file, expected a header");
    if (!splitCsvRecord(line_, header_))
      throw InputError(path, "line 1", "malformed CSV header (unbalanced quotes)");
    for (std::size_t i = 0; i < header_.size(); ++i) column_[header_[i]] = i;
    for (const auto& r : required)
      if (!column_.count(r)) throw InputError(path, "line 1", "missing column '" + r + "'");
  }

  // The next non-empty row, false at the end of the file.
  bool next() {
    while (nextLine()) {
      if (line_.empty()) continue;
      if (!splitCsvRecord(line_, row_))
        throw InputError(path_, place(), "malformed CSV row (unbalanced quotes)");
      if (row_.size() != header_.size())
        throw InputError(path_, place(),
                         "has " + std::to_string(row_.size()) + " fields, header has " +
                             std::to_string(header_.size()));
      return true;
    }
    return false;
  }

  bool has(const std::string& name) const { return column_.count(name) != 0; }
  const std::string& text(const std::string& name) const { return row_[column_.at(name)]; }
  double number(const std::string& name) const {
    const std::string& s = text(name);
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0')
      throw InputError(path_, place() + ", column " + name, "not a number: '" + s + "'");
    return v;
  }
  std::string place() const { return "line " + std::to_string(line_number_); }
  const std::string& path() const { return path_; }

 private:
  // Lines longer than any row cosim writes are refused before they fill memory.
  static constexpr std::size_t kMaxLineBytes = 1 << 16;

  bool nextLine() {
    buffer_.resize(kMaxLineBytes + 2);
    in_.getline(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    const auto got = static_cast<std::size_t>(in_.gcount());
    if (in_.bad()) throw InputError(path_, "", "cannot read file");
    const bool at_end = in_.eof();
    if (in_.fail()) {
      if (got == 0 && at_end) return false;
      ++line_number_;
      throw InputError(path_, place(),
                       "longer than " + std::to_string(kMaxLineBytes) + " characters");
    }
    ++line_number_;
    // gcount() counts the line end it consumed; the last line may have none.
    line_.assign(buffer_.data(), at_end ? got : got - 1);
    if (!line_.empty() && line_.back() == '\r') line_.pop_back();
    return true;
  }

  std::string path_;
  std::ifstream in_;
  std::vector<char> buffer_;
  std::string line_;
  std::size_t line_number_ = 0;
  std::vector<std::string> header_, row_;
  std::map<std::string, std::size_t> column_;
};

VehicleLog& vehicleNamed(RunLog& log, const std::string& name) {
  for (auto& v : log.vehicles)
    if (v.name == name) return v;
  log.vehicles.emplace_back().name = name;
  return log.vehicles.back();
}

// A sample's time: finite, within the run, never going back for one vehicle (lookups by time
// are binary searches, and the video's frame count follows the last time).
double sampleTime(const CsvLogReader& in, const LogBounds& bounds, double previous,
                  const std::string& who) {
  const double t = in.number("t");
  if (!std::isfinite(t) || t < 0.0 || t > bounds.max_time)
    throw InputError(in.path(), in.place() + ", column t",
                     "time " + std::to_string(t) + " s is outside the run (0 to " +
                         std::to_string(bounds.max_time) + " s)");
  if (t < previous)
    throw InputError(in.path(), in.place() + ", column t", "time goes backwards for " + who);
  return t;
}

}  // namespace

std::string timeseriesCsv(const RunLog& log) {
  std::string out;
  for (const char* name : kTimeseriesColumns) out += std::string(name) + ",";
  out += "vehicle\n";
  for (const VehicleLog& v : log.vehicles) {
    for (const LogSample& s : v.samples) {
      for (double x : timeseriesRow(s)) put(out, x);
      out += csvField(v.name) + "\n";
    }
  }
  return out;
}

std::vector<std::pair<std::string, std::vector<double>>> timeseriesColumns(const RunLog& log,
                                                                           std::size_t vehicle) {
  std::vector<std::pair<std::string, std::vector<double>>> columns;
  if (vehicle >= log.vehicles.size()) return columns;
  const std::vector<LogSample>& samples = log.vehicles[vehicle].samples;
  for (const char* name : kTimeseriesColumns) {
    columns.emplace_back(name, std::vector<double>());
    columns.back().second.reserve(samples.size());
  }
  for (const LogSample& s : samples) {
    const TimeseriesRow row = timeseriesRow(s);
    for (std::size_t c = 0; c < row.size(); ++c) columns[c].second.push_back(row[c]);
  }
  return columns;
}

std::string pathCsv(const RunLog& log) {
  const bool many = log.vehicles.size() > 1;
  std::string out = many ? "x,y,z,vehicle\n" : "x,y,z\n";
  for (const VehicleLog& v : log.vehicles) {
    for (const Eigen::Vector3d& p : v.planned_path) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%.9g,%.9g,%.9g", p.x(), p.y(), p.z());
      out += buf;
      if (many) {  // appended piece by piece: GCC 12's -Wrestrict misfires on operator+ chains
        out += ',';
        out += csvField(v.name);
      }
      out += '\n';
    }
  }
  return out;
}

std::string movingObstaclesCsv(const RunLog& log) {
  std::string out = "t,name,x,y,z\n";
  for (const MovingObstacleLog& o : log.moving_obstacles) {
    for (std::size_t i = 0; i < o.t.size() && i < o.pos.size(); ++i) {
      char buf[128];
      std::snprintf(buf, sizeof buf, "%.9g,", o.t[i]);
      out += buf;
      out += csvField(o.name);
      std::snprintf(buf, sizeof buf, ",%.9g,%.9g,%.9g\n", o.pos[i].x(), o.pos[i].y(), o.pos[i].z());
      out += buf;
    }
  }
  return out;
}

void readTimeseriesCsv(const std::string& path, RunLog& log, const LogBounds& bounds) {
  const std::vector<std::string> required = {"t",  "ref_x", "ref_y", "ref_z", "x",
                                             "y",  "z",     "qw",    "qx",    "qy",
                                             "qz", "vx",    "vy",    "vz",    "vehicle"};
  // First the rows per vehicle, so that each vehicle's samples are allocated once (a growing
  // vector holds up to twice its samples while it copies).
  {
    CsvLogReader count(path, required);
    std::map<std::string, std::size_t> rows;
    while (count.next()) {
      std::size_t& n = rows[count.text("vehicle")];
      if (++n > bounds.max_rows_per_vehicle)
        throw InputError(path, count.place(),
                         "more than " + std::to_string(bounds.max_rows_per_vehicle) +
                             " rows for vehicle '" + count.text("vehicle") +
                             "', more than the scenario's run can log");
      if (rows.size() > bounds.max_vehicles)
        throw InputError(
            path, count.place(),
            "more vehicles than the scenario has (" + std::to_string(bounds.max_vehicles) + ")");
    }
    for (const auto& [name, n] : rows) vehicleNamed(log, name).samples.reserve(n);
  }
  CsvLogReader in(path, required);
  const bool has_ref_vel = in.has("ref_vx"), has_thrust = in.has("thrust3"),
             has_estimate = in.has("est_qz");
  while (in.next()) {
    const auto f = [&](const char* name) { return in.number(name); };
    VehicleLog& v = vehicleNamed(log, in.text("vehicle"));
    LogSample s;
    s.t = sampleTime(in, bounds, v.samples.empty() ? 0.0 : v.samples.back().t,
                     "vehicle '" + v.name + "'");
    s.ref_pos = {f("ref_x"), f("ref_y"), f("ref_z")};
    if (has_ref_vel) s.ref_vel = {f("ref_vx"), f("ref_vy"), f("ref_vz")};
    s.pos = {f("x"), f("y"), f("z")};
    s.vel = {f("vx"), f("vy"), f("vz")};
    s.att = Eigen::Quaterniond(f("qw"), f("qx"), f("qy"), f("qz")).normalized();
    if (has_thrust) s.rotor_thrust = {f("thrust0"), f("thrust1"), f("thrust2"), f("thrust3")};
    // The estimate (logs from before sensing was simulated have none: the truth was seen).
    if (has_estimate) {
      s.est_pos = {f("est_x"), f("est_y"), f("est_z")};
      s.est_vel = {f("est_vx"), f("est_vy"), f("est_vz")};
      s.est_att =
          Eigen::Quaterniond(f("est_qw"), f("est_qx"), f("est_qy"), f("est_qz")).normalized();
    } else {
      s.est_pos = s.pos;
      s.est_vel = s.vel;
      s.est_att = s.att;
    }
    v.samples.push_back(s);
  }
}

void readPathCsv(const std::string& path, RunLog& log, const LogBounds& bounds) {
  CsvLogReader in(path, {"x", "y", "z"});
  const bool named = in.has("vehicle");
  std::size_t rows = 0;
  while (in.next()) {
    if (++rows > bounds.max_path_points)
      throw InputError(path, in.place(),
                       "more than " + std::to_string(bounds.max_path_points) + " waypoints");
    const Eigen::Vector3d p(in.number("x"), in.number("y"), in.number("z"));
    if (named)
      vehicleNamed(log, in.text("vehicle")).planned_path.push_back(p);
    else if (!log.vehicles.empty())
      log.vehicles.front().planned_path.push_back(p);
    else
      vehicleNamed(log, "").planned_path.push_back(p);
  }
}

void readMovingObstaclesCsv(const std::string& path, RunLog& log, const LogBounds& bounds) {
  CsvLogReader in(path, {"t", "name", "x", "y", "z"});
  const std::size_t first = log.moving_obstacles.size();
  std::size_t rows = 0;
  // Saturating: the unbounded defaults would wrap their product to 1.
  const std::size_t max_rows =
      bounds.max_moving_obstacles != 0 && bounds.max_rows_per_vehicle >
                                              std::numeric_limits<std::size_t>::max() /
                                                  bounds.max_moving_obstacles
          ? std::numeric_limits<std::size_t>::max()
          : bounds.max_rows_per_vehicle * bounds.max_moving_obstacles;
  while (in.next()) {
    if (++rows > max_rows)
      throw InputError(path, in.place(), "more rows than the scenario's run can log");
    const std::string& name = in.text("name");
    auto it = std::find_if(log.moving_obstacles.begin() + static_cast<std::ptrdiff_t>(first),
                           log.moving_obstacles.end(),
                           [&](const MovingObstacleLog& o) { return o.name == name; });
    if (it == log.moving_obstacles.end()) {
      if (log.moving_obstacles.size() - first >= bounds.max_moving_obstacles)
        throw InputError(path, in.place(), "more moving obstacles than the scenario has");
      log.moving_obstacles.emplace_back().name = name;
      it = log.moving_obstacles.end() - 1;
    }
    it->t.push_back(
        sampleTime(in, bounds, it->t.empty() ? 0.0 : it->t.back(), "obstacle '" + name + "'"));
    it->pos.emplace_back(in.number("x"), in.number("y"), in.number("z"));
  }
}

}  // namespace cosim
