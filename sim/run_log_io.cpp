#include "sim/run_log_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "planning/input_error.h"

namespace cosim {

namespace {

const char* const kTimeseriesHeader =
    "t,ref_x,ref_y,ref_z,ref_vx,ref_vy,ref_vz,x,y,z,vx,vy,vz,qw,qx,qy,qz,roll_deg,pitch_deg,"
    "yaw_deg,p,q,r,cmd0,cmd1,cmd2,cmd3,thrust0,thrust1,thrust2,thrust3,saturated,est_x,est_y,est_z,"
    "est_vx,est_vy,est_vz,est_qw,est_qx,est_qy,est_qz,w0,w1,w2,w3,vehicle";

void put(std::string& out, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g,", v);
  out += buf;
}

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

// Reads a CSV file with a header into rows of named fields.
struct CsvTable {
  std::map<std::string, std::size_t> column;
  std::vector<std::vector<std::string>> rows;
};

CsvTable readCsv(const std::string& path, const std::vector<std::string>& required) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open file");
  CsvTable t;
  std::string line;
  if (!std::getline(in, line)) throw InputError(path, "line 1", "empty file, expected a header");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const auto header = splitCsvLine(line);
  for (std::size_t i = 0; i < header.size(); ++i) t.column[header[i]] = i;
  for (const auto& r : required)
    if (!t.column.count(r)) throw InputError(path, "line 1", "missing column '" + r + "'");
  for (int n = 2; std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    auto f = splitCsvLine(line);
    if (f.size() != header.size())
      throw InputError(path, "line " + std::to_string(n),
                       "has " + std::to_string(f.size()) + " fields, header has " +
                           std::to_string(header.size()));
    t.rows.push_back(std::move(f));
  }
  return t;
}

double field(const CsvTable& t, const std::vector<std::string>& row, const std::string& name,
             const std::string& path, std::size_t row_index) {
  const std::string& s = row[t.column.at(name)];
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0')
    throw InputError(path, "line " + std::to_string(row_index + 2) + ", column " + name,
                     "not a number: '" + s + "'");
  return v;
}

VehicleLog& vehicleNamed(RunLog& log, const std::string& name) {
  for (auto& v : log.vehicles)
    if (v.name == name) return v;
  log.vehicles.emplace_back().name = name;
  return log.vehicles.back();
}

}  // namespace

std::string timeseriesCsv(const RunLog& log) {
  std::string out = std::string(kTimeseriesHeader) + "\n";
  for (const VehicleLog& v : log.vehicles) {
    for (const LogSample& s : v.samples) {
      put(out, s.t);
      for (int i = 0; i < 3; ++i) put(out, s.ref_pos[i]);
      for (int i = 0; i < 3; ++i) put(out, s.ref_vel[i]);
      for (int i = 0; i < 3; ++i) put(out, s.pos[i]);
      for (int i = 0; i < 3; ++i) put(out, s.vel[i]);
      put(out, s.att.w());
      put(out, s.att.x());
      put(out, s.att.y());
      put(out, s.att.z());
      const Eigen::Matrix3d R = s.att.toRotationMatrix();
      put(out, std::atan2(R(2, 1), R(2, 2)) * 180.0 / M_PI);
      put(out, -std::asin(std::clamp(R(2, 0), -1.0, 1.0)) * 180.0 / M_PI);
      put(out, std::atan2(R(1, 0), R(0, 0)) * 180.0 / M_PI);
      for (int i = 0; i < 3; ++i) put(out, s.omega[i]);
      for (int i = 0; i < 4; ++i) put(out, s.rotor_cmd[i]);
      for (int i = 0; i < 4; ++i) put(out, s.rotor_thrust[i]);
      out += s.saturated ? "1," : "0,";
      for (int i = 0; i < 3; ++i) put(out, s.est_pos[i]);
      for (int i = 0; i < 3; ++i) put(out, s.est_vel[i]);
      put(out, s.est_att.w());
      put(out, s.est_att.x());
      put(out, s.est_att.y());
      put(out, s.est_att.z());
      for (int i = 0; i < 4; ++i) put(out, s.rotor_speed[i]);
      out += v.name + "\n";
    }
  }
  return out;
}

std::string pathCsv(const RunLog& log) {
  const bool many = log.vehicles.size() > 1;
  std::string out = many ? "x,y,z,vehicle\n" : "x,y,z\n";
  for (const VehicleLog& v : log.vehicles) {
    for (const Eigen::Vector3d& p : v.planned_path) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%.9g,%.9g,%.9g", p.x(), p.y(), p.z());
      out += buf;
      out += many ? "," + v.name + "\n" : "\n";
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
      out += o.name;
      std::snprintf(buf, sizeof buf, ",%.9g,%.9g,%.9g\n", o.pos[i].x(), o.pos[i].y(), o.pos[i].z());
      out += buf;
    }
  }
  return out;
}

void readTimeseriesCsv(const std::string& path, RunLog& log) {
  const CsvTable t = readCsv(path, {"t", "ref_x", "ref_y", "ref_z", "x", "y", "z", "qw", "qx", "qy",
                                    "qz", "vx", "vy", "vz", "vehicle"});
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const auto& r = t.rows[i];
    auto f = [&](const char* name) { return field(t, r, name, path, i); };
    LogSample s;
    s.t = f("t");
    s.ref_pos = {f("ref_x"), f("ref_y"), f("ref_z")};
    if (t.column.count("ref_vx")) s.ref_vel = {f("ref_vx"), f("ref_vy"), f("ref_vz")};
    s.pos = {f("x"), f("y"), f("z")};
    s.vel = {f("vx"), f("vy"), f("vz")};
    s.att = Eigen::Quaterniond(f("qw"), f("qx"), f("qy"), f("qz")).normalized();
    if (t.column.count("thrust3"))
      s.rotor_thrust = {f("thrust0"), f("thrust1"), f("thrust2"), f("thrust3")};
    // The estimate (logs from before sensing was simulated have none: the truth was seen).
    if (t.column.count("est_qz")) {
      s.est_pos = {f("est_x"), f("est_y"), f("est_z")};
      s.est_vel = {f("est_vx"), f("est_vy"), f("est_vz")};
      s.est_att = Eigen::Quaterniond(f("est_qw"), f("est_qx"), f("est_qy"), f("est_qz")).normalized();
    } else {
      s.est_pos = s.pos;
      s.est_vel = s.vel;
      s.est_att = s.att;
    }
    vehicleNamed(log, r[t.column.at("vehicle")]).samples.push_back(s);
  }
}

void readPathCsv(const std::string& path, RunLog& log) {
  const CsvTable t = readCsv(path, {"x", "y", "z"});
  const bool named = t.column.count("vehicle") != 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const auto& r = t.rows[i];
    const Eigen::Vector3d p(field(t, r, "x", path, i), field(t, r, "y", path, i),
                            field(t, r, "z", path, i));
    if (named)
      vehicleNamed(log, r[t.column.at("vehicle")]).planned_path.push_back(p);
    else if (!log.vehicles.empty())
      log.vehicles.front().planned_path.push_back(p);
    else
      vehicleNamed(log, "").planned_path.push_back(p);
  }
}

void readMovingObstaclesCsv(const std::string& path, RunLog& log) {
  const CsvTable t = readCsv(path, {"t", "name", "x", "y", "z"});
  const std::size_t first = log.moving_obstacles.size();
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const auto& r = t.rows[i];
    const std::string& name = r[t.column.at("name")];
    auto it = std::find_if(log.moving_obstacles.begin() + static_cast<std::ptrdiff_t>(first),
                           log.moving_obstacles.end(),
                           [&](const MovingObstacleLog& o) { return o.name == name; });
    if (it == log.moving_obstacles.end()) {
      log.moving_obstacles.emplace_back().name = name;
      it = log.moving_obstacles.end() - 1;
    }
    const double time = field(t, r, "t", path, i);
    // The renderer looks positions up by time (a binary search).
    if (!it->t.empty() && time < it->t.back())
      throw InputError(path, "line " + std::to_string(i + 2),
                       "time goes backwards for obstacle '" + name + "'");
    it->t.push_back(time);
    it->pos.emplace_back(field(t, r, "x", path, i), field(t, r, "y", path, i),
                         field(t, r, "z", path, i));
  }
}

}  // namespace cosim
