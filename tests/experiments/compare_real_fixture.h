#pragma once
// The fixture of the compare-real end-to-end tests: a real `cosim run` of a short flight, whose
// own flown path is written back as a "real" log (late, moved, padded, broken) and compared.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "sim/run_log_io.h"
#include "tests/support/cosim_command.h"
#include "tests/support/json_fields.h"

namespace cosim::test {

// A vector [x, y, z] of compare.json (NaN if it is not there).
inline Eigen::Vector3d vectorField(const std::string& json, const std::string& key) {
  const std::string head = "\"" + key + "\": [";
  const auto at = json.find(head);
  Eigen::Vector3d d = Eigen::Vector3d::Constant(std::nan(""));
  if (at != std::string::npos)
    std::sscanf(json.c_str() + at + head.size(), "%lf, %lf, %lf", &d[0], &d[1], &d[2]);
  return d;
}

inline Eigen::Vector3d startOffset(const std::string& json) {
  return vectorField(json, "start_offset_m");
}

// An 8 s minimum-snap flight through three waypoints of the Crazyflie-class quadrotor in an
// empty room.
inline const char* kScenario =
    "world: {bounds: {min: [0, 0, 0], max: [6, 5, 3]}}\n"
    "vehicles: [{name: cf, model: cf2, start: [1, 1, 1], "
    "waypoints: [[3, 1.5, 1.3], [4, 3, 1.5], [2, 3.5, 1.2]]}]\n"
    "planner: {name: theta_star, resolution: 0.25, margin: 0.1}\n"
    "trajectory: {mode: minimum_snap, max_speed: 1.5, max_acceleration: 2.0}\n"
    "controller: {name: geometric}\n"
    "sim: {timestep: 0.001, control_rate: 500, max_time: 20, seed: 3}\n";

class CompareReal : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::filesystem::path(freshDir("compare-real"));
    std::filesystem::create_directories(*dir_);
    std::ofstream(*dir_ / "flight.yaml") << kScenario;
    const CommandResult r = runCosim("run " + (*dir_ / "flight.yaml").string() + " --out " +
                                     (*dir_ / "run").string() + " --no-video --no-images --quiet");
    ASSERT_EQ(r.status, 0) << r.err;
    RunLog log;
    readTimeseriesCsv((*dir_ / "run" / "timeseries.csv").string(), log);
    samples_ = new std::vector<LogSample>(log.vehicles.at(0).samples);
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(*dir_);
    delete dir_;
    delete samples_;
  }

  // The flown path as a CSV log: t + delay, position + shift; `pad` seconds of standing still
  // before and after; with `reference`, the run's reference (moved the same way) as ref_ columns.
  static std::filesystem::path writeLog(const std::string& name, double delay,
                                        const Eigen::Vector3d& shift, double pad = 0.0,
                                        bool reference = false) {
    const auto path = *dir_ / name;
    std::ofstream out(path);
    out << (reference ? "t,x,y,z,ref_x,ref_y,ref_z\n" : "t,x,y,z\n");
    char row[240];
    const auto put = [&](double t, const LogSample& s) {
      const Eigen::Vector3d p = s.pos + shift, r = s.ref_pos + shift;
      std::snprintf(row, sizeof row, "%.17g,%.9g,%.9g,%.9g", t + delay, p.x(), p.y(), p.z());
      out << row;
      if (reference) {
        std::snprintf(row, sizeof row, ",%.9g,%.9g,%.9g", r.x(), r.y(), r.z());
        out << row;
      }
      out << "\n";
    };
    const LogSample &first = samples_->front(), &last = samples_->back();
    for (double t = first.t - pad; t < first.t - 1e-9; t += 0.01) put(t, first);
    for (const LogSample& s : *samples_) put(s.t, s);
    for (double t = last.t + 0.01; t <= last.t + pad; t += 0.01) put(t, last);
    return path;
  }

  static CommandResult compare(const std::filesystem::path& log, const std::string& extra = "",
                               const std::string& out = "cmp") {
    return runCosim("compare-real " + (*dir_ / "run").string() + " " + log.string() + " --out " +
                    (*dir_ / out).string() + " " + extra);
  }
  static std::string result() { return slurp(*dir_ / "cmp" / "compare.json"); }

  static inline std::filesystem::path* dir_ = nullptr;
  static inline std::vector<LogSample>* samples_ = nullptr;
};

}  // namespace cosim::test
