// End-to-end: the cosim program on the bundled default scenario and on bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/support/cosim_command.h"
#include "tests/support/json_fields.h"

using namespace cosim::test;

TEST(CliRun, DefaultScenarioReachesItsGoalWithZeroCollisionsAndRendersAVideo) {
  const auto dir = freshDir("default");
  // The video as a 10x time-lapse: its frames are rendered and encoded as at full length, a tenth
  // as many (the full-length video made this test take one to three minutes).
  const CommandResult r = runCosim("run --quiet --video-speed 10 --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* f : {"metrics.json", "timeseries.csv", "path.csv", "final.png", "video.mp4"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  const std::string m = slurp(dir / "metrics.json");
  EXPECT_TRUE(jsonTrue(m, "reached_goal")) << m;
  EXPECT_EQ(jsonNumber(m, "collisions"), 0.0) << m;
  EXPECT_GT(jsonNumber(m, "min_clearance_m"), 0.0) << m;
  EXPECT_GT(jsonNumber(m, "flown_length_m"), jsonNumber(m, "planned_length_m") * 0.9) << m;
  // Minimum snap under the geometric controller tracks its reference closely (the tracking targets:
  // RMSE <= 5 cm, max error <= 15 cm for the 1.5 kg quad at up to 3 m/s).
  EXPECT_LT(jsonNumber(m, "rmse_m"), 0.05) << m;
  EXPECT_LT(jsonNumber(m, "max_error_m"), 0.15) << m;
  EXPECT_LE(jsonNumber(m, "max_speed_mps"), 3.3) << m;

  // The video's length matches the simulated time at the scenario's 30 fps, sped up 10 times.
  const std::string probe = "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                            "stream=nb_read_frames,codec_name,pix_fmt -of csv=p=0 " +
                            (dir / "video.mp4").string() + " > " + (dir / "probe.txt").string();
  ASSERT_EQ(std::system(probe.c_str()), 0);
  const std::string info = slurp(dir / "probe.txt");
  EXPECT_NE(info.find("h264"), std::string::npos) << info;
  EXPECT_NE(info.find("yuv420p"), std::string::npos) << info;
  const double frames = std::strtod(info.substr(info.rfind(',') + 1).c_str(), nullptr);
  const double sim_time = jsonNumber(m, "sim_time_s");
  EXPECT_NEAR(frames, std::floor(sim_time * 30 / 10) + 1, 1.0) << info;
  std::filesystem::remove_all(dir);
}

TEST(CliRun, MissingScenarioFileExitsTwoWithOneLineAndWritesNothing) {
  const auto dir = freshDir("missing");
  const CommandResult r = runCosim("run /no/such/file.yaml --out " + dir.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/no/such/file.yaml"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "metrics.json"));
}

TEST(CliRun, BadSetOverrideNamesTheKeyAndExitsTwo) {
  const auto dir = freshDir("badset");
  const CommandResult r = runCosim("run --no-video --out " + dir.string() + " --set sim.timestep=-1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("sim.timestep"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "metrics.json"));
  std::filesystem::remove_all(dir);
}

TEST(CliRun, UnknownCommandLineOptionExitsTwo) {
  const CommandResult r = runCosim("run --no-such-flag");
  EXPECT_EQ(r.status, 2);
}

TEST(CliRun, HelpAndVersionExitZero) {
  EXPECT_EQ(runCosim("--help").status, 0);
  const CommandResult v = runCosim("--version");
  EXPECT_EQ(v.status, 0);
  EXPECT_NE(v.out.find("cosim"), std::string::npos);
}

TEST(CliRun, RerenderFromTheLogWritesAPngWithoutSimulating) {
  const auto dir = freshDir("rerender");
  ASSERT_EQ(runCosim("run --quiet --no-video --out " + dir.string() + " --set sim.max_time=3").status, 1)
      << "a 3 s flight cannot reach the goal, so the run reports failure";
  ASSERT_TRUE(std::filesystem::exists(dir / "timeseries.csv"));
  const CommandResult r = runCosim("render " + dir.string() + " --camera top --out " + (dir / "top.png").string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_GT(std::filesystem::file_size(dir / "top.png"), 10000u);
  std::filesystem::remove_all(dir);
}
