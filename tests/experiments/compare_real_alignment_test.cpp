// compare-real's alignment as a result: a log of the run's own path, late and high, reports the
// lag and the height (not absorbed by default, removed only when asked); logs stamped in epoch
// seconds are placed and the search ends; an interrupt stops a long comparison.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <nlohmann/json.hpp>

#include "tests/experiments/compare_real_fixture.h"
#include "tests/experiments/usd_log_writer.h"
#include "tests/support/spawned_cosim.h"

namespace cosim::test {
namespace {

TEST_F(CompareReal, ALogSixtyMillisecondsLateAndThreeCentimetresHighReportsBoth) {
  // (A second of standing still before and after, so that the log covers the window at its own
  // clock's zero offset too.)
  const auto log = writeLog("late-high.csv", 0.06, Eigen::Vector3d(0.0, 0.0, 0.03), 1.0);
  CommandResult r = compare(log);
  ASSERT_EQ(r.status, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(result());
  std::printf("late and high, default: %s\n", j.dump().c_str());
  EXPECT_EQ(j["alignment"], "time");
  EXPECT_NEAR(j["time_offset_s"].get<double>(), 0.06, 0.005);
  EXPECT_NEAR(j["mean_offset_m"][0].get<double>(), 0.0, 0.002);
  EXPECT_NEAR(j["mean_offset_m"][1].get<double>(), 0.0, 0.002);
  EXPECT_NEAR(j["mean_offset_m"][2].get<double>(), 0.03, 0.002);
  EXPECT_FALSE(j["start_offset_fitted"].get<bool>());
  // The height stays in the real error: above the simulated one by about 3 cm in quadrature.
  const double real = j["real_rmse_m"], sim = j["sim_rmse_m"];
  EXPECT_NEAR(real, std::hypot(sim, 0.03), 0.005);
  // Every alignment, side by side: with the 3D offset fitted the flight is the run's own.
  EXPECT_NEAR(j["rmse_by_alignment"]["time+xyz"]["ratio"].get<double>(), 1.0, 0.05);
  EXPECT_NEAR(j["rmse_by_alignment"]["time+xy"]["real"].get<double>(), real, 1e-3);
  EXPECT_TRUE(j["rmse_by_alignment"].contains("none"));  // the log's clock covers the window
  EXPECT_GT(j["rmse_by_alignment"]["none"]["real"].get<double>(), real);  // 60 ms late counts
  // Per axis: the simulated and the real flight lag the reference alike (the real one is the
  // simulated one, moved in time by exactly what was fitted).
  for (int a = 0; a < 3; ++a) {
    ASSERT_TRUE(j["axis_lag_s"]["sim"][a].is_number()) << a;
    EXPECT_NEAR(j["axis_lag_s"]["real"][a].get<double>(), j["axis_lag_s"]["sim"][a].get<double>(),
                0.005);
    EXPECT_NEAR(j["amplitude_ratio"]["real"][a].get<double>(),
                j["amplitude_ratio"]["sim"][a].get<double>(), 0.02);
  }
  ASSERT_EQ(j["warnings"].size(), 2u) << j["warnings"];
  EXPECT_NE(j["warnings"][0].get<std::string>().find("fitted time shift 0.0"), std::string::npos);
  EXPECT_NE(j["warnings"][0].get<std::string>().find("is above 0.05 s"), std::string::npos);
  EXPECT_NE(j["warnings"][1].get<std::string>().find("(z 0.03"), std::string::npos);
  EXPECT_NE(r.err.find("cosim: warning: fitted time shift"), std::string::npos) << r.err;
  // Asked to, the 3D offset is fitted away: the ratio of the run's own flight is 1.
  r = compare(log, "--align time+xyz");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(result());
  EXPECT_EQ(j["alignment"], "time+xyz");
  EXPECT_NEAR(j["ratio"].get<double>(), 1.0, 0.05);
  EXPECT_NEAR(j["start_offset_m"][2].get<double>(), 0.03, 0.002);
  EXPECT_NEAR(j["mean_offset_m"][2].get<double>(), 0.03, 0.002);  // reported all the same
  // Nothing fitted: the log's own clock, 60 ms late.
  r = compare(log, "--align none");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(result());
  EXPECT_EQ(j["time_offset_s"].get<double>(), 0.0);
  EXPECT_FALSE(j["time_offset_fitted"].get<bool>());
}

TEST_F(CompareReal, LogsStampedInEpochSecondsArePlacedAndTheSearchEnds) {
  // A CSV at 8.6e9 s (where a double resolves 2e-6 s, coarser than the search's 1e-6 s bracket)
  // and a uSD log at 1e16 us: each finishes (the watchdog would end a spinning search at 120 s:
  // status 124) and finds its offset.
  const auto csv = writeLog("epoch.csv", 8.6e9 + 0.7, Eigen::Vector3d::Zero());
  CommandResult r = runCosim("compare-real " + (*dir_ / "run").string() + " " + csv.string() +
                                 " --out " + (*dir_ / "cmp").string(),
                             {}, 120);
  ASSERT_EQ(r.status, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(result());
  EXPECT_NEAR(j["time_offset_s"].get<double>() - 8.6e9, 0.7, 0.02);
  EXPECT_NEAR(j["ratio"].get<double>(), 1.0, 0.02);
  UsdLogWriter w(2);
  w.addType({0xFFFF, "fixedFrequency", {"locSrv.x(f)", "locSrv.y(f)", "locSrv.z(f)"}});
  for (const LogSample& s : *samples_)
    w.record(0xFFFF, 1e10 + s.t,
             UsdLogWriter::f32(static_cast<float>(s.pos.x())) +
                 UsdLogWriter::f32(static_cast<float>(s.pos.y())) +
                 UsdLogWriter::f32(static_cast<float>(s.pos.z())));
  std::ofstream(*dir_ / "epoch.bin", std::ios::binary) << w.bytes();
  r = runCosim("compare-real " + (*dir_ / "run").string() + " " + (*dir_ / "epoch.bin").string() +
                   " --out " + (*dir_ / "cmp").string(),
               {}, 120);
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(result());
  EXPECT_NEAR(j["time_offset_s"].get<double>() - 1e10, 0.0, 0.002);
  EXPECT_NEAR(j["ratio"].get<double>(), 1.0, 0.02);
}

TEST_F(CompareReal, SigtermDuringALongComparisonExitsOneWithinThreeSecondsWritingNothing) {
  // The flight in 20 minutes of standing still either side: the fits search 2400 s of offsets.
  const auto log = writeLog("long.csv", 1200.0, Eigen::Vector3d::Zero(), 1200.0);
  const auto out = *dir_ / "cmp-interrupted", err = *dir_ / "interrupted.err";
  const pid_t pid = spawnCosim(
      {"compare-real", (*dir_ / "run").string(), log.string(), "--out", out.string()}, err);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForText(err, "cosim: placing the log", std::chrono::seconds(60))) << slurp(err);
  kill(pid, SIGTERM);
  EXPECT_TRUE(waitForText(err, "interrupted", std::chrono::seconds(3))) << slurp(err);
  EXPECT_EQ(waitExitWithin(pid, std::chrono::seconds(30)), 1);
  EXPECT_FALSE(std::filesystem::exists(out / "compare.json"));
}

}  // namespace
}  // namespace cosim::test
