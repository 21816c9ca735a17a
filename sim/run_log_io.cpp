#include "sim/run_log_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "core/csv_text.h"
#include "core/input_error.h"
#include "core/input_file.h"

namespace cosim {

namespace {

// One numeric column of timeseries.csv: its header name and its value in a sample. The file
// writer and timeseriesColumns both read this table, so that the columns a front end gets in
// memory are the file's, in the file's order. (The last column, the vehicle's name, is text.)
struct TimeseriesColumn {
  const char* name;
  double (*value)(const LogSample&);
};

// Euler angles (ZYX, degrees) of an attitude, as the file has always written them.
double rollDeg(const LogSample& s) {
  const Eigen::Matrix3d R = s.att.toRotationMatrix();
  return std::atan2(R(2, 1), R(2, 2)) * 180.0 / M_PI;
}
double pitchDeg(const LogSample& s) {
  const Eigen::Matrix3d R = s.att.toRotationMatrix();
  return -std::asin(std::clamp(R(2, 0), -1.0, 1.0)) * 180.0 / M_PI;
}
double yawDeg(const LogSample& s) {
  const Eigen::Matrix3d R = s.att.toRotationMatrix();
  return std::atan2(R(1, 0), R(0, 0)) * 180.0 / M_PI;
}

const TimeseriesColumn kTimeseriesColumns[] = {
    {"t", [](const LogSample& s) { return s.t; }},
    {"ref_x", [](const LogSample& s) { return s.ref_pos.x(); }},
    {"ref_y", [](const LogSample& s) { return s.ref_pos.y(); }},
    {"ref_z", [](const LogSample& s) { return s.ref_pos.z(); }},
    {"ref_vx", [](const LogSample& s) { return s.ref_vel.x(); }},
    {"ref_vy", [](const LogSample& s) { return s.ref_vel.y(); }},
    {"ref_vz", [](const LogSample& s) { return s.ref_vel.z(); }},
    {"x", [](const LogSample& s) { return s.pos.x(); }},
    {"y", [](const LogSample& s) { return s.pos.y(); }},
    {"z", [](const LogSample& s) { return s.pos.z(); }},
    {"vx", [](const LogSample& s) { return s.vel.x(); }},
    {"vy", [](const LogSample& s) { return s.vel.y(); }},
    {"vz", [](const LogSample& s) { return s.vel.z(); }},
    {"qw", [](const LogSample& s) { return s.att.w(); }},
    {"qx", [](const LogSample& s) { return s.att.x(); }},
    {"qy", [](const LogSample& s) { return s.att.y(); }},
    {"qz", [](const LogSample& s) { return s.att.z(); }},
    {"roll_deg", [](const LogSample& s) { return rollDeg(s); }},
    {"pitch_deg", [](const LogSample& s) { return pitchDeg(s); }},
    {"yaw_deg", [](const LogSample& s) { return yawDeg(s); }},
    {"p", [](const LogSample& s) { return s.omega.x(); }},
    {"q", [](const LogSample& s) { return s.omega.y(); }},
    {"r", [](const LogSample& s) { return s.omega.z(); }},
    {"cmd0", [](const LogSample& s) { return s.rotor_cmd[0]; }},
    {"cmd1", [](const LogSample& s) { return s.rotor_cmd[1]; }},
    {"cmd2", [](const LogSample& s) { return s.rotor_cmd[2]; }},
    {"cmd3", [](const LogSample& s) { return s.rotor_cmd[3]; }},
    {"thrust0", [](const LogSample& s) { return s.rotor_thrust[0]; }},
    {"thrust1", [](const LogSample& s) { return s.rotor_thrust[1]; }},
    {"thrust2", [](const LogSample& s) { return s.rotor_thrust[2]; }},
    {"thrust3", [](const LogSample& s) { return s.rotor_thrust[3]; }},
    {"saturated", [](const LogSample& s) { return s.saturated ? 1.0 : 0.0; }},
    {"est_x", [](const LogSample& s) { return s.est_pos.x(); }},
    {"est_y", [](const LogSample& s) { return s.est_pos.y(); }},
    {"est_z", [](const LogSample& s) { return s.est_pos.z(); }},
    {"est_vx", [](const LogSample& s) { return s.est_vel.x(); }},
    {"est_vy", [](const LogSample& s) { return s.est_vel.y(); }},
    {"est_vz", [](const LogSample& s) { return s.est_vel.z(); }},
    {"est_qw", [](const LogSample& s) { return s.est_att.w(); }},
    {"est_qx", [](const LogSample& s) { return s.est_att.x(); }},
    {"est_qy", [](const LogSample& s) { return s.est_att.y(); }},
    {"est_qz", [](const LogSample& s) { return s.est_att.z(); }},
    {"w0", [](const LogSample& s) { return s.rotor_speed[0]; }},
    {"w1", [](const LogSample& s) { return s.rotor_speed[1]; }},
    {"w2", [](const LogSample& s) { return s.rotor_speed[2]; }},
    {"w3", [](const LogSample& s) { return s.rotor_speed[3]; }},
};

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

// A sample's time: finite, within the run, never going back for one vehicle or obstacle
// (lookups by time are binary searches, and the video's frame count follows the last time).
// Each logs one row per logged control step, so its times rise strictly: a repeated time is a
// repeated row. `previous`: its last time (none for its first row); `who`: "vehicle 'uav1'".
double sampleTime(const CsvLogReader& in, const LogBounds& bounds,
                  const std::optional<double>& previous, const std::string& who) {
  const double t = in.number("t");
  if (!std::isfinite(t) || t < 0.0 || t > bounds.max_time)
    throw InputError(in.path(), in.place() + ", column t",
                     "time " + std::to_string(t) + " s is outside the run (0 to " +
                         std::to_string(bounds.max_time) + " s)");
  if (previous && t < *previous)
    throw InputError(in.path(), in.place() + ", column t", "time goes backwards for " + who);
  if (previous && t == *previous)
    throw InputError(in.path(), in.place() + ", column t",
                     "time " + std::to_string(t) + " s again for " + who +
                         ": a repeated row (a run logs each instant once)");
  return t;
}

// A log must hold what run.json says the run wrote (a file cut at a line boundary parses, and
// is shorter), and at least one row.
void checkRowCount(const std::string& path, std::size_t rows,
                   const std::optional<std::size_t>& logged) {
  if (rows == 0)
    throw InputError(path, "line 2", "no rows after the header: the log holds no flight");
  if (logged && rows < *logged)
    throw InputError(path, "line " + std::to_string(rows + 2),
                     "the log ends after " + std::to_string(rows) + " rows, but the run wrote " +
                         std::to_string(*logged) + " (run.json): the file was cut short");
  if (logged && rows > *logged)
    throw InputError(path, "line " + std::to_string(*logged + 2),
                     "more rows than the " + std::to_string(*logged) +
                         " the run wrote (run.json): the file was added to");
}

}  // namespace

std::string timeseriesCsv(const RunLog& log) {
  std::string out;
  for (const TimeseriesColumn& c : kTimeseriesColumns) out += std::string(c.name) + ",";
  out += "vehicle\n";
  for (const VehicleLog& v : log.vehicles) {
    for (const LogSample& s : v.samples) {
      for (const TimeseriesColumn& c : kTimeseriesColumns) put(out, c.value(s));
      out += csvField(v.name) + "\n";
    }
  }
  return out;
}

std::vector<std::pair<std::string, std::vector<double>>> timeseriesColumns(const RunLog& log,
                                                                           std::size_t vehicle) {
  std::vector<std::pair<std::string, std::vector<double>>> columns;
  const std::vector<LogSample>& samples = log.vehicles.at(vehicle).samples;
  for (const TimeseriesColumn& c : kTimeseriesColumns) {
    std::vector<double>& values = columns.emplace_back(c.name, std::vector<double>()).second;
    values.reserve(samples.size());
    for (const LogSample& s : samples) values.push_back(c.value(s));
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
  std::size_t total = 0;
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
    for (const auto& [name, n] : rows) total += n;
    if (total == 0) checkRowCount(path, total, std::nullopt);
    for (const auto& [name, n] : rows) vehicleNamed(log, name).samples.reserve(n);
  }
  CsvLogReader in(path, required);
  const bool has_ref_vel = in.has("ref_vx"), has_thrust = in.has("thrust3"),
             has_estimate = in.has("est_qz");
  while (in.next()) {
    // NaN would make the flown path vanish from the picture; only a run that diverged logs it.
    const auto f = [&](const char* name) {
      const double value = in.number(name);
      if (!std::isfinite(value) && !bounds.non_finite_allowed)
        throw InputError(
            path, in.place() + ", column " + name,
            "not a finite number: '" + in.text(name) + "' (only a run that diverged logs one)");
      return value;
    };
    VehicleLog& v = vehicleNamed(log, in.text("vehicle"));
    LogSample s;
    s.t = sampleTime(in, bounds,
                     v.samples.empty() ? std::nullopt : std::optional<double>(v.samples.back().t),
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
  checkRowCount(path, total, bounds.timeseries_rows);  // after the rows: a bad row is named first
}

void readPathCsv(const std::string& path, RunLog& log, const LogBounds& bounds) {
  CsvLogReader in(path, {"x", "y", "z"});
  const bool named = in.has("vehicle");
  std::size_t rows = 0;
  while (in.next()) {
    if (++rows > bounds.max_path_points)
      throw InputError(path, in.place(),
                       "more than " + std::to_string(bounds.max_path_points) + " waypoints");
    if (bounds.path_rows && rows > *bounds.path_rows) break;
    const Eigen::Vector3d p(in.number("x"), in.number("y"), in.number("z"));
    if (!p.allFinite()) throw InputError(path, in.place(), "a waypoint that is not a finite point");
    if (named)
      vehicleNamed(log, in.text("vehicle")).planned_path.push_back(p);
    else if (!log.vehicles.empty())
      log.vehicles.front().planned_path.push_back(p);
    else
      vehicleNamed(log, "").planned_path.push_back(p);
  }
  // A run without a plan writes a header alone: only run.json's count tells a cut file apart.
  if (bounds.path_rows && rows != *bounds.path_rows) checkRowCount(path, rows, bounds.path_rows);
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
    it->t.push_back(sampleTime(in, bounds,
                               it->t.empty() ? std::nullopt : std::optional<double>(it->t.back()),
                               "obstacle '" + name + "'"));
    it->pos.emplace_back(in.number("x"), in.number("y"), in.number("z"));
  }
}

}  // namespace cosim
