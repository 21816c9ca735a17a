// cosim compare-real end to end: a real `cosim run` of a short flight, its own flown path
// written as a "real" log 0.7 s late (and moved, and padded, and broken), compared back.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "tests/experiments/compare_real_fixture.h"
#include "tests/experiments/usd_log_writer.h"

namespace cosim::test {
namespace {

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
  const CommandResult r = compare(writeLog("moved.csv", 0.7 + 2.0, shift, 2.0), "--align time+xyz");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = result();
  std::printf("padded, moved log: %s", json.c_str());
  EXPECT_NEAR(jsonNumber(json, "time_offset_s"), 2.7, 0.02);
  EXPECT_NEAR(jsonNumber(json, "ratio"), 1.0, 0.02);
  EXPECT_TRUE(jsonTrue(json, "start_offset_fitted"));
  EXPECT_NEAR((startOffset(json) - shift).norm(), 0.0, 1e-3) << json;
}

TEST_F(CompareReal, AHorizontalOffsetIsReportedByDefaultAndFittedWhenAsked) {
  // A log without a reference: only the time is fitted unless --align says more, so the offset
  // stays in the real error and is reported (a real vehicle's start is never the simulated one;
  // the user decides whether that counts).
  const Eigen::Vector3d shift(-0.25, 0.5, 0.0);
  const auto log = writeLog("aside.csv", 0.7, shift);
  CommandResult r = compare(log);
  ASSERT_EQ(r.status, 0) << r.err;
  std::string json = result();
  EXPECT_FALSE(jsonTrue(json, "start_offset_fitted"));
  // (Unfitted, 0.56 m aside pulls the time fit by some 40 ms, and with it the mean offset.)
  EXPECT_NEAR((vectorField(json, "mean_offset_m") - shift).norm(), 0.0, 0.03) << json;
  EXPECT_GT(jsonNumber(json, "ratio"), 5.0);  // 0.56 m aside counts
  EXPECT_NE(r.err.find("cosim: warning: mean offset of the real flight from the simulated one "
                       "(x -0.2"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("is above 0.02 m: it is in the real error"), std::string::npos) << r.err;
  r = compare(log, "--align time+xy");
  ASSERT_EQ(r.status, 0) << r.err;
  json = result();
  EXPECT_TRUE(jsonTrue(json, "start_offset_fitted"));
  EXPECT_NEAR(jsonNumber(json, "time_offset_s"), 0.7, 0.02);
  EXPECT_NEAR(jsonNumber(json, "ratio"), 1.0, 0.02);
  EXPECT_NEAR((startOffset(json) - shift).norm(), 0.0, 1e-3) << json;
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
  EXPECT_NE(json.find("\"alignment_target\": \"the log's reference against the run's "
                      "reference\""),
            std::string::npos);
  EXPECT_NE(json.find("\"alignment\": \"time+xy\""), std::string::npos);  // the default with one
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
  EXPECT_NE(r.err.find("scenario.yaml: cannot open (is this a run folder?)"), std::string::npos)
      << r.err;
  r = compare(*dir_ / "short.csv", "--vehicle nobody", "bad");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no vehicle 'nobody' in the run (it has cf)"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(*dir_ / "bad" / "compare.json"));
}

}  // namespace
}  // namespace cosim::test
