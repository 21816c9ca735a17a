// `cosim render RUN_DIR` shows the moving obstacles where the run saw them: the run folder's
// moving_obstacles.csv holds their logged positions, and the re-render reads them back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "run/run_pipeline.h"
#include "sim/moving_obstacle_motion.h"
#include "sim/run_log.h"
#include "sim/run_log_io.h"
#include "sim/scenario.h"
#include "tests/support/cosim_command.h"

using namespace cosim;

namespace {

// A PNG's pixels as RGB bytes (decoded by ffmpeg, which the videos need anyway).
std::string pixels(const std::filesystem::path& png) {
  const auto raw = png.string() + ".rgb";
  const std::string cmd = "ffmpeg -loglevel error -y -i '" + png.string() +
                          "' -f rawvideo -pix_fmt rgb24 '" + raw + "'";
  if (std::system(cmd.c_str()) != 0) return {};
  return test::slurp(raw);
}

// Pixels whose colour differs by more than 30 of 255 in some channel.
std::size_t differingPixels(const std::string& a, const std::string& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 2 < a.size() && i + 2 < b.size(); i += 3) {
    int d = 0;
    for (int c = 0; c < 3; ++c)
      d = std::max(
          d, std::abs(static_cast<unsigned char>(a[i + c]) - static_cast<unsigned char>(b[i + c])));
    n += d > 30 ? 1 : 0;
  }
  return n;
}

}  // namespace

TEST(MovingObstaclesRerender, RunFolderLogsEachObstacleWhereItMovedAndTheRerenderMatchesFinalPng) {
  // 12 s: long enough for the cylinders to move metres (the robot need not arrive); overrides,
  // not edits, so the folder's scenario.yaml says the same to the re-render.
  Scenario s = loadScenario(
      std::string(COSIM_SOURCE_DIR) + "/experiments/scenarios/ground_moving_obstacles.yaml",
      {"sim.max_time=12", "render.width=320", "render.height=180"});
  RunRequest request;
  request.out_dir = test::freshDir("moving-rerender");
  std::filesystem::create_directories(request.out_dir);
  request.video = false;
  executeRun(s, request);
  const auto& dir = request.out_dir;
  ASSERT_TRUE(std::filesystem::exists(dir / "moving_obstacles.csv"));

  RunLog reread;
  readMovingObstaclesCsv((dir / "moving_obstacles.csv").string(), reread);
  ASSERT_EQ(reread.moving_obstacles.size(), s.moving_obstacles.size());
  for (std::size_t i = 0; i < s.moving_obstacles.size(); ++i) {
    const MovingObstacleLog& o = reread.moving_obstacles[i];
    EXPECT_EQ(o.name, movingObstacleName(i));
    ASSERT_GT(o.t.size(), 100u);
    EXPECT_GT(o.t.back(), 11.0);
    // On its patrol line (these patrol along y at a fixed x), within the line's ends.
    const MovingObstacleSpec& spec = s.moving_obstacles[i];
    const double y_lo = std::min(spec.path[0].y(), spec.path[1].y()) - 1e-6;
    const double y_hi = std::max(spec.path[0].y(), spec.path[1].y()) + 1e-6;
    for (std::size_t k = 0; k < o.t.size(); ++k) {
      ASSERT_NEAR(o.pos[k].x(), spec.path[0].x(), 1e-6) << o.name << " at " << o.t[k];
      ASSERT_GE(o.pos[k].y(), y_lo);
      ASSERT_LE(o.pos[k].y(), y_hi);
    }
    // And it moved: speed 0.25..0.35 m/s for ~12 s (a re-render that left it at its start
    // would be metres off).
    EXPECT_GT((o.pos.back() - o.pos.front()).norm(), 2.5) << o.name;
  }

  // The re-render from the folder's files draws the final frame the run drew from its log in
  // memory, but for a few edge pixels (the files keep 9 digits). Without moving_obstacles.csv
  // it drew the three cylinders at their starts: hundreds of pixels off even at 320 x 180.
  const test::CommandResult r =
      test::runCosim("render '" + dir.string() + "' --out '" + (dir / "again.png").string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string original = pixels(dir / "final.png"), again = pixels(dir / "again.png");
  ASSERT_EQ(original.size(), 320u * 180u * 3u);
  ASSERT_EQ(again.size(), original.size());
  EXPECT_LT(differingPixels(original, again), 20u);
  std::filesystem::remove(dir / "moving_obstacles.csv");
  ASSERT_EQ(
      test::runCosim("render '" + dir.string() + "' --out '" + (dir / "without.png").string() + "'")
          .status,
      0);
  EXPECT_GT(differingPixels(original, pixels(dir / "without.png")), 100u);
  std::filesystem::remove_all(dir);
}

TEST(MovingObstaclesRerender, CsvReadsBackEveryObstacleSampleToNineDigits) {
  RunLog log;
  for (int i = 0; i < 2; ++i) {
    MovingObstacleLog& o = log.moving_obstacles.emplace_back();
    o.name = movingObstacleName(static_cast<std::size_t>(i));
    for (int k = 0; k < 50; ++k) {
      o.t.push_back(0.02 * k);
      o.pos.emplace_back(4.25 + i, 0.75 + 0.3 * 0.02 * k + 1.0 / 3.0, 0.0);
    }
  }
  const auto dir = test::freshDir("moving-csv");
  std::filesystem::create_directories(dir);
  const auto file = dir / "moving_obstacles.csv";
  std::ofstream(file) << movingObstaclesCsv(log);
  RunLog reread;
  readMovingObstaclesCsv(file.string(), reread);
  ASSERT_EQ(reread.moving_obstacles.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const MovingObstacleLog &a = log.moving_obstacles[i], &b = reread.moving_obstacles[i];
    EXPECT_EQ(b.name, a.name);
    ASSERT_EQ(b.t.size(), a.t.size());
    for (std::size_t k = 0; k < a.t.size(); ++k) {
      EXPECT_NEAR(b.t[k], a.t[k], 1e-9);
      EXPECT_LT((b.pos[k] - a.pos[k]).norm(), 1e-8);
    }
  }
  // Times going backwards for one obstacle (a hand-edited file) are refused, naming the line.
  std::ofstream(file) << "t,name,x,y,z\n0.1,moving0,1,2,0\n0.05,moving0,1,2,0\n";
  RunLog bad;
  try {
    readMovingObstaclesCsv(file.string(), bad);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}
