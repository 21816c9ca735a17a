// `cosim run` writes viewer.html beside index.html, which links it, and `cosim export-mcap`
// turns the same folder into an MCAP file; without three.js the run still succeeds and says
// once why the page is missing.
#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "render/viewer_page.h"
#include "tests/support/cosim_command.h"

using namespace cosim::test;

namespace {

// The default scenario on a short hop (about 4 s of flight), no video (the pictures stay: with
// --no-images there is no index.html either).
const char* kShortRun = "run --quiet --no-video --set 'vehicles[0].goal=[6,5,2.5]'";

}  // namespace

TEST(RunViewer, RunFolderHoldsTheReplayLinkedFromIndexAndExportsMcap) {
  if (!cosim::loadThreeJs().missing.empty()) GTEST_SKIP() << cosim::loadThreeJs().missing;
  const auto dir = freshDir("run-viewer");
  const CommandResult run = runCosim(std::string(kShortRun) + " --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string page = slurp(dir / "viewer.html");
  EXPECT_NE(page.find("REVISION=\"111\""), std::string::npos) << "three.js r111 is embedded";
  EXPECT_NE(page.find("\"name\":\"uav1\""), std::string::npos);
  EXPECT_EQ(page.find("<script src="), std::string::npos) << "no script is loaded from elsewhere";
  EXPECT_NE(slurp(dir / "index.html").find("href=\"viewer.html\""), std::string::npos);

  const CommandResult mcap = runCosim("export-mcap " + dir.string());
  ASSERT_EQ(mcap.status, 0) << mcap.err;
  const std::string file = slurp(dir / "run.mcap");
  ASSERT_GT(file.size(), 16u);
  EXPECT_EQ(file.substr(0, 8), std::string("\x89MCAP0\r\n", 8));
  EXPECT_EQ(file.substr(file.size() - 8), std::string("\x89MCAP0\r\n", 8));
  EXPECT_NE(file.find("foxglove.FrameTransform"), std::string::npos);
  EXPECT_NE(mcap.out.find("messages on 6 channels"), std::string::npos) << mcap.out;

  // Beside it a Foxglove layout: a 3D panel on the scene topics in the world frame, plots of
  // position and error on topics the file really has.
  EXPECT_NE(mcap.out.find("run.layout.json beside it"), std::string::npos) << mcap.out;
  const auto layout = nlohmann::json::parse(slurp(dir / "run.layout.json"));
  const auto& three = layout.at("configById").at("3D!cosim");
  EXPECT_EQ(three.at("followTf"), "world");
  for (const char* topic : {"/world", "/vehicles", "/paths"}) {
    EXPECT_TRUE(three.at("topics").at(topic).at("visible").get<bool>()) << topic;
    EXPECT_NE(file.find(topic), std::string::npos) << topic;
  }
  const auto& position = layout.at("configById").at("Plot!position").at("paths");
  ASSERT_EQ(position.size(), 3u);
  EXPECT_EQ(position[2].at("value"), "/vehicles/uav1/state.position.z");
  const auto& error = layout.at("configById").at("Plot!error").at("paths");
  ASSERT_EQ(error.size(), 2u);
  EXPECT_EQ(error[0].at("value"), "/vehicles/uav1/state.error_m");
  EXPECT_NE(file.find("/vehicles/uav1/state"), std::string::npos);
  EXPECT_EQ(layout.at("layout").at("first"), "3D!cosim");
  std::filesystem::remove_all(dir);
}

TEST(RunViewer, WithoutThreeJsTheRunSucceedsAndSaysWhyOnce) {
  const auto dir = freshDir("run-no-viewer");
  ::setenv("COSIM_THREE_DIR", (dir / "none").c_str(), 1);  // inherited by the program
  const CommandResult run = runCosim(std::string(kShortRun) + " --out " + dir.string());
  ::unsetenv("COSIM_THREE_DIR");
  EXPECT_EQ(run.status, 0) << run.err;
  const std::string why = "viewer.html was not written: three.js not found";
  const auto first = run.err.find(why);
  EXPECT_NE(first, std::string::npos) << run.err;
  EXPECT_EQ(run.err.find(why, first + 1), std::string::npos) << "said once";
  EXPECT_FALSE(std::filesystem::exists(dir / "viewer.html"));
  EXPECT_TRUE(std::filesystem::exists(dir / "metrics.json"));
  std::filesystem::remove_all(dir);
}
