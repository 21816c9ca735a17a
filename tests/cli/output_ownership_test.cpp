// End to end: cosim never deletes or overwrites what it did not write (core/output_manifest.h).
// A folder that never held a cosim run keeps the user's files under cosim's names when a command
// is refused; a command into it is refused (exit 2, one line naming the file) before any work; a
// file cosim wrote but the user changed since is not replaced by a rerun; frames are not rendered
// over a folder of the user's.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/cosim_command.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

const char* kQuickFlight =
    "world: {bounds: {min: [0, 0, 0], max: [12, 8, 4]}}\n"
    "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [4, 2, 1]}]\n"
    "sim: {max_time: 10}\n";

// The user's files under the names `cosim run` writes (figures/ with a file in it).
void plantUsersRunFiles(const fs::path& dir) {
  fs::create_directories(dir / "figures");
  for (const char* name :
       {"index.html", "final.png", "metrics.json", "timeseries.csv", "path.csv", "viewer.html"})
    std::ofstream(dir / name) << "the user's " << name << "\n";
  std::ofstream(dir / "figures" / "thesis.png") << "the user's figure\n";
}

void expectUsersRunFilesKept(const fs::path& dir) {
  for (const char* name :
       {"index.html", "final.png", "metrics.json", "timeseries.csv", "path.csv", "viewer.html"})
    EXPECT_EQ(slurp(dir / name), std::string("the user's ") + name + "\n") << name;
  EXPECT_EQ(slurp(dir / "figures" / "thesis.png"), "the user's figure\n");
}

// Exit 2 with one line on stderr that names `file`.
void expectRefusedNaming(const CommandResult& r, const std::string& file) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

class OutputOwnership : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = makeFreshDir(std::string("ownership-") +
                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::ofstream(dir_ / "s.yaml") << kQuickFlight;
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(OutputOwnership, ARunWithAMissingScenarioLeavesTheUsersFilesInPlace) {
  const fs::path out = dir_ / "mine";
  plantUsersRunFiles(out);
  const CommandResult r =
      runCosim("run /nonexistent.yaml --no-video --quiet --out " + out.string());
  EXPECT_EQ(r.status, 2) << r.err;
  expectUsersRunFilesKept(out);
}

TEST_F(OutputOwnership, ARunIntoAFolderOfTheUsersFilesIsRefusedNamingOne) {
  const fs::path out = dir_ / "mine";
  plantUsersRunFiles(out);
  const CommandResult r = runCosim("run " + (dir_ / "s.yaml").string() +
                                   " --no-video --no-images --quiet --out " + out.string());
  expectRefusedNaming(r, out.string());
  EXPECT_NE(r.err.find("not written by cosim, or changed since"), std::string::npos) << r.err;
  expectUsersRunFilesKept(out);
  EXPECT_FALSE(fs::exists(out / "scenario.yaml"));  // refused before any work
}

TEST_F(OutputOwnership, APlanRerunReplacesItsOwnFilesButNotOneTheUserChanged) {
  const fs::path out = dir_ / "plan";
  const std::string plan =
      "plan " + (dir_ / "s.yaml").string() + " --planner astar --out " + out.string();
  ASSERT_EQ(runCosim(plan).status, 0);
  ASSERT_TRUE(fs::exists(out / ".cosim-manifest"));
  const CommandResult again = runCosim(plan);  // the manifest proves both files cosim's
  ASSERT_EQ(again.status, 0) << again.err;

  std::ofstream(out / "path.csv", std::ios::app) << "1,2,3\n";  // the user's edit
  const std::string edited = slurp(out / "path.csv");
  const std::string plan_json = slurp(out / "plan.json");
  expectRefusedNaming(runCosim(plan), (out / "path.csv").string());
  EXPECT_EQ(slurp(out / "path.csv"), edited);
  EXPECT_EQ(slurp(out / "plan.json"), plan_json);  // nothing removed before the refusal
}

TEST_F(OutputOwnership, APlanWithBadInputRemovesNothing) {
  const fs::path out = dir_ / "plan";
  fs::create_directories(out);
  std::ofstream(out / "path.csv") << "the user's\n";
  const CommandResult r = runCosim("plan " + (dir_ / "missing.yaml").string() +
                                   " --planner astar --out " + out.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(slurp(out / "path.csv"), "the user's\n");
}

TEST_F(OutputOwnership, AMapfWithAMissingScenarioFileKeepsTheUsersExecutionFolder) {
  const fs::path out = dir_ / "mapf";
  fs::create_directories(out / "execution");
  std::ofstream(out / "execution" / "notes.md") << "the user's\n";
  const CommandResult r = runCosim("mapf " COSIM_SOURCE_DIR "/experiments/maps/empty-8-8.map " +
                                   (dir_ / "missing.scen").string() +
                                   " --agents 2 --planner cbs --out " + out.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(slurp(out / "execution" / "notes.md"), "the user's\n");
}

TEST_F(OutputOwnership, FramesIntoAnExistingFolderOfTheUsersAreRefusedAndTheFolderKept) {
  const fs::path run = dir_ / "run";
  const CommandResult flown = runCosim("run " + (dir_ / "s.yaml").string() +
                                       " --no-video --no-images --quiet --out " + run.string());
  ASSERT_EQ(flown.status, 0) << flown.err;
  EXPECT_FALSE(fs::exists(run / "index.html"));  // --no-images: no page either
  const fs::path frames = dir_ / "holiday";
  fs::create_directories(frames);
  std::ofstream(frames / "beach.jpg") << "the user's\n";
  const CommandResult r =
      runCosim("render " + run.string() +
               " --frames --width 64 --height 64 --fps 2 --quiet --out " + frames.string());
  expectRefusedNaming(r, (frames / "beach.jpg").string());
  EXPECT_EQ(slurp(frames / "beach.jpg"), "the user's\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(frames), fs::directory_iterator()), 1);

  // A video under a name promising another format is refused, not written as MP4.
  const CommandResult gif =
      runCosim("render " + run.string() + " --quiet --out " + (dir_ / "x.gif").string());
  expectRefusedNaming(gif, (dir_ / "x.gif").string());
  EXPECT_FALSE(fs::exists(dir_ / "x.gif"));
}

TEST_F(OutputOwnership, AnOutputNameLongerThanAFileSystemAllowsExitsTwoInOneLine) {
  const std::string name(300, 'n');
  const CommandResult r =
      runCosim("plan " + (dir_ / "s.yaml").string() + " --out " + (dir_ / name).string());
  expectRefusedNaming(r, "300 bytes");
}

}  // namespace
}  // namespace cosim::test
