// cosim compare-real end to end: a real `cosim run` of a short flight, its own flown path
// written as a "real" log 0.7 s late (and moved, and padded, and broken), compared back.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "sim/run_log_io.h"
#include "tests/experiments/usd_log_writer.h"
#include "tests/support/cosim_command.h"
#include "tests/support/json_fields.h"

namespace cosim::test {
namespace {

// compare.json's start_offset_m (NaN if it is not there).
Eigen::Vector3d startOffset(const std::string& json) {
  const auto at = json.find("\"start_offset_m\": [");
  Eigen::Vector3d d = Eigen::Vector3d::Constant(std::nan(""));
  if (at != std::string::npos)
    std::sscanf(json.c_str() + at + 19, "%lf, %lf, %lf", &d[0], &d[1], &d[2]);
  return d;
}

// An 8 s minimum-snap flight through three waypoints of the Crazyflie-class quadrotor in an
// empty room.
const char* kScenario =
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
      std::snprintf(row, sizeof row, "%.9g,%.9g,%.9g,%.9g", t + delay, p.x(), p.y(), p.z());
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

  static std::filesystem::path* dir_;
  static std::vector<LogSample>* samples_;
};
std::filesystem::path* CompareReal::dir_ = nullptr;
std::vector<LogSample>* CompareReal::samples_ = nullptr;

TEST_F(CompareReal, OwnFlightLoggedLateRecoversTheOffsetAndARatioOfOne) {
  const CommandResult r = compare(writeLog("late.csv", 0.7, Eigen::Vector3d::Zero()));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = result();
  std::printf("late log: %s", json.c_str());
  EXPECT_NEAR(jsonNumber(json, "time_offset_s"), 0.7, 0.02);
  EXPECT_NEAR(jsonNumber(json, "ratio"), 1.0, 0.02);
  EXPECT_GT(jsonNumber(json, "sim_rmse_m"), 1e-4);  // a real flight's error, not zero
  EXPECT_GT(jsonNumber(json, "samples"), 1000);
  EXPECT_FALSE(jsonTrue(json, "start_offset_fitted"));  // a planned flight: absolute frame
  for (const char* f : {"compare.md", "compare.png", "compare.svg"})
    EXPECT_TRUE(std::filesystem::is_regular_file(*dir_ / "cmp" / f)) << f;
}

TEST_F(CompareReal, PaddedAndMovedLogIsPlacedInTimeAndSpace) {
  // Standing still 2 s before and after: the offset has room on both sides of 0.7 s.
  const Eigen::Vector3d shift(0.4, -0.3, 0.2);
  const CommandResult r =
      compare(writeLog("moved.csv", 0.7 + 2.0, shift, 2.0), "--start-offset fit");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = result();
  std::printf("padded, moved log: %s", json.c_str());
  EXPECT_NEAR(jsonNumber(json, "time_offset_s"), 2.7, 0.02);
  EXPECT_NEAR(jsonNumber(json, "ratio"), 1.0, 0.02);
  EXPECT_TRUE(jsonTrue(json, "start_offset_fitted"));
  EXPECT_NEAR((startOffset(json) - shift).norm(), 0.0, 1e-3) << json;
}

TEST_F(CompareReal, RelativeReferenceFitsTheStartOffsetByItself) {
  // The run folder as a run of a reference flown relative to the start would leave it: only
  // vehicles[i].reference.relative of its scenario.yaml is read.
  const auto run = *dir_ / "run", relative = *dir_ / "relative-run";
  std::filesystem::create_directories(relative);
  std::filesystem::copy_file(run / "timeseries.csv", relative / "timeseries.csv");
  std::ofstream(relative / "scenario.yaml")
      << "vehicles:\n  - name: cf\n    model: cf2\n    start: [1, 1, 1]\n"
      << "    reference: {file: figure8.csv, timescale: 1.0, relative: true}\n";
  const CommandResult r =
      runCosim("compare-real " + relative.string() + " " +
               writeLog("relative.csv", 0.7, Eigen::Vector3d(-0.25, 0.5, 0.0)).string() +
               " --out " + (*dir_ / "cmp-relative").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = slurp(*dir_ / "cmp-relative" / "compare.json");
  EXPECT_TRUE(jsonTrue(json, "relative_reference"));
  EXPECT_TRUE(jsonTrue(json, "start_offset_fitted"));
  EXPECT_NEAR(jsonNumber(json, "time_offset_s"), 0.7, 0.02);
  EXPECT_NEAR(jsonNumber(json, "ratio"), 1.0, 0.02);
  EXPECT_NEAR((startOffset(json) - Eigen::Vector3d(-0.25, 0.5, 0.0)).norm(), 0.0, 1e-3) << json;
}

TEST_F(CompareReal, AligningToTheReferenceAbsorbsTheVehiclesLag) {
  // Matched to the reference instead of the simulated flight, the fitted offset takes up the
  // vehicle's lag behind its reference, and the "real" error comes out below the simulated one.
  const CommandResult r =
      compare(writeLog("late.csv", 0.7, Eigen::Vector3d::Zero()), "--align-to reference");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = result();
  std::printf("aligned to the reference: ratio %.4f, offset %.5f s\n", jsonNumber(json, "ratio"),
              jsonNumber(json, "time_offset_s"));
  EXPECT_LT(jsonNumber(json, "ratio"), 0.99);
  EXPECT_LT(jsonNumber(json, "time_offset_s"), 0.7);
  EXPECT_NEAR(jsonNumber(json, "time_offset_s"), 0.7, 0.01);
}

TEST_F(CompareReal, ALogWithItsReferenceIsPlacedByItAndMeasuredAgainstIt) {
  // Moved by 0.3 m with its reference: the real error is the position against the log's own
  // reference, so the move does not count (against the run's reference it would be 0.3 m).
  const Eigen::Vector3d shift(0.3, 0.0, 0.0);
  const CommandResult r = compare(writeLog("with-ref.csv", 1.9, shift, 1.0, true));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = result();
  EXPECT_NE(json.find("\"alignment\": \"the log's reference against the run's reference\""),
            std::string::npos);
  EXPECT_NEAR(jsonNumber(json, "time_offset_s"), 1.9, 0.002);
  EXPECT_NEAR(jsonNumber(json, "ratio"), 1.0, 0.02);
  EXPECT_NEAR((startOffset(json) - shift).norm(), 0.0, 1e-3) << json;
}

TEST_F(CompareReal, AUsdLogOfTheFlightIsReadAndPlacedLikeTheCsv) {
  // The flight as the uSD-card deck would log it at 500 Hz: locSrv (single precision) in the
  // fixed-frequency event, the clock counting from power-on (12.3 s before the run began).
  UsdLogWriter w(2);
  w.addType({0xFFFF,
             "fixedFrequency",
             {"pm.vbat(f)", "locSrv.x(f)", "locSrv.y(f)", "locSrv.z(f)", "locSrv.qw(e)"}});
  for (const LogSample& s : *samples_)
    w.record(0xFFFF, 12.3 + s.t,
             UsdLogWriter::f32(3.9f) + UsdLogWriter::f32(static_cast<float>(s.pos.x())) +
                 UsdLogWriter::f32(static_cast<float>(s.pos.y())) +
                 UsdLogWriter::f32(static_cast<float>(s.pos.z())) +
                 UsdLogWriter::integer(0x3C00, 2));
  std::ofstream(*dir_ / "flight.bin", std::ios::binary) << w.bytes();
  const CommandResult r = compare(*dir_ / "flight.bin");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = result();
  EXPECT_NE(json.find("\"log_format\": \"Crazyflie uSD log version 2\""), std::string::npos);
  EXPECT_NE(json.find("locSrv.x,locSrv.y,locSrv.z (event fixedFrequency)"), std::string::npos);
  EXPECT_NEAR(jsonNumber(json, "time_offset_s"), 12.3, 0.002);
  EXPECT_NEAR(jsonNumber(json, "ratio"), 1.0, 0.02);
}

TEST_F(CompareReal, WritesIntoTheRunFolderByDefaultAndARerunThereClearsIt) {
  const auto run = *dir_ / "rerun";
  const std::string again = "run " + (*dir_ / "flight.yaml").string() + " --out " + run.string() +
                            " --no-video --no-images --quiet";
  ASSERT_EQ(runCosim(again).status, 0);
  const auto log = writeLog("late-again.csv", 0.7, Eigen::Vector3d::Zero());
  ASSERT_EQ(runCosim("compare-real " + run.string() + " " + log.string()).status, 0);
  for (const char* f : {"compare.json", "compare.md", "compare.png", "compare.svg"})
    EXPECT_TRUE(std::filesystem::is_regular_file(run / f)) << f;
  // A new run in the folder: the comparison was of the old one.
  ASSERT_EQ(runCosim(again).status, 0);
  for (const char* f : {"compare.json", "compare.md", "compare.png", "compare.svg"})
    EXPECT_FALSE(std::filesystem::exists(run / f)) << f;
}

TEST_F(CompareReal, BadLogsAndRunFoldersAreExitTwoNamingTheFile) {
  // A uSD log whose CRC is wrong.
  UsdLogWriter w(2);
  w.addType({1, "fixedFrequency", {"locSrv.x(f)", "locSrv.y(f)", "locSrv.z(f)"}});
  for (int k = 0; k < 20; ++k)
    w.record(1, 0.01 * k, UsdLogWriter::f32(1) + UsdLogWriter::f32(2) + UsdLogWriter::f32(3));
  std::ofstream(*dir_ / "bad.bin", std::ios::binary) << w.bytes(true);
  CommandResult r = compare(*dir_ / "bad.bin", "", "bad");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("bad.bin: byte"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("CRC-32 mismatch"), std::string::npos) << r.err;
  // A log far shorter than the reference's window.
  std::ofstream(*dir_ / "short.csv") << "t,x,y,z\n"
                                     << [] {
                                          std::string s;
                                          for (int k = 0; k < 20; ++k)
                                            s += std::to_string(0.01 * k) + ",1,1,1\n";
                                          return s;
                                        }();
  r = compare(*dir_ / "short.csv", "", "bad");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("short.csv: no overlap with the run"), std::string::npos) << r.err;
  // Not a run folder.
  r = runCosim("compare-real " + dir_->string() + " " + (*dir_ / "short.csv").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("scenario.yaml: missing"), std::string::npos) << r.err;
  r = compare(*dir_ / "short.csv", "--vehicle nobody", "bad");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no vehicle 'nobody' in the run (it has cf)"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(*dir_ / "bad" / "compare.json"));
}

}  // namespace
}  // namespace cosim::test
