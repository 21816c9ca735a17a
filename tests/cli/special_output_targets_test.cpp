// End to end: an output named by --out that is a FIFO or a device is refused with exit 2 and
// left as it was (writing to a temporary name and renaming it over the target replaced the
// node with a regular file: as root that destroyed the machine's /dev/null), and an existing
// folder given as an output file is refused before any work.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/cosim_command.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

const char* kScenario =
    "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}}\n"
    "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [8, 2, 1]}]\n"
    "planner: {name: astar, resolution: 0.5}\nsim: {max_time: 30}\n";

class SpecialOutputTargets : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = freshDir(std::string("special-out-") +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    std::ofstream(dir_ / "s.yaml") << kScenario;
    fifo_ = dir_ / "pipe.xml";
    ASSERT_EQ(::mkfifo(fifo_.c_str(), 0644), 0);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // The command refused the target with exit 2 naming it, and the FIFO is still one.
  void expectRefused(const CommandResult& r, const fs::path& target, const std::string& option) {
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.err, "cosim: " + target.string() + ": " + option +
                         ": is a FIFO, not a regular file: cosim writes its outputs as new "
                         "regular files and would replace it; name a file instead\n");
    EXPECT_TRUE(fs::is_fifo(fs::symlink_status(target)));
  }
  fs::path dir_, fifo_;
};

TEST_F(SpecialOutputTargets, ExportMjcfRefusesAFifoAndADevice) {
  expectRefused(runCosim("export-mjcf " + (dir_ / "s.yaml").string() + " --out " + fifo_.string()),
                fifo_, "--out");
  // A node like /dev/null of our own, where this process may make one (root with CAP_MKNOD).
  const fs::path device = dir_ / "null";
  if (::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0) {
    const CommandResult r =
        runCosim("export-mjcf " + (dir_ / "s.yaml").string() + " --out " + device.string());
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("is a character device, not a regular file"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_character_file(fs::symlink_status(device)));
  }
}

TEST_F(SpecialOutputTargets, GridBenchRefusesAFifoWithoutRemovingIt) {
  const std::string data = COSIM_TEST_DATA_DIR "/movingai/";
  expectRefused(runCosim("grid-bench " + data + "arena.map " + data +
                         "arena.map.scen --planner astar --out " + fifo_.string()),
                fifo_, "--out");
}

TEST_F(SpecialOutputTargets, RenderRefusesAFifoAsItsPicture) {
  const fs::path run = dir_ / "run";
  const CommandResult flown = runCosim("run " + (dir_ / "s.yaml").string() +
                                       " --no-video --no-images --quiet --out " + run.string());
  ASSERT_EQ(flown.status, 0) << flown.err;
  const fs::path picture = dir_ / "device.png";
  ASSERT_EQ(::mkfifo(picture.c_str(), 0644), 0);
  expectRefused(runCosim("render " + run.string() + " --out " + picture.string() + " --at 1"),
                picture, "--out");
}

TEST_F(SpecialOutputTargets, ExportMjcfIntoAnExistingFolderExitsTwoBeforeAnyWork) {
  // The scenario is not even read: the output is checked first.
  const CommandResult r =
      runCosim("export-mjcf " + (dir_ / "missing.yaml").string() + " --out " + dir_.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err, "cosim: " + dir_.string() + ": --out: is a folder; give a file name\n");
}

}  // namespace
}  // namespace cosim::test
