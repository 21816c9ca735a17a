// A run folder holds what `cosim render` needs: the references flown are copied into it, so it
// renders after the original reference file moved; and a defect in its own scenario.yaml is
// reported at that file and line, not at the original scenario's.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/support/cosim_command.h"

using namespace cosim::test;

namespace {

namespace fs = std::filesystem;

const char* kReference = "t,x,y,z\n0,0,0,0\n1,0.25,0,0\n2,0.5,0,0\n";

class RunFolderRender : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = makeFreshDir("run-folder-render");
    fs::create_directories(dir_ / "refs");
    std::ofstream(dir_ / "refs" / "hop.csv") << kReference;
    std::ofstream(dir_ / "s.yaml") << "world: {bounds: {min: [0, 0, 0], max: [6, 6, 3]}}\n"
                                      "vehicles:\n"
                                      "  - name: uav1\n"
                                      "    model: cf2\n"
                                      "    start: [2, 2, 1]\n"
                                      "    reference: {file: refs/hop.csv, relative: true}\n"
                                      "sim: {max_time: 4}\n";
    run_ = dir_ / "run";
    const CommandResult r = runCosim("run " + (dir_ / "s.yaml").string() +
                                     " --no-video --no-images --quiet --out " + run_.string());
    ASSERT_EQ(r.status, 0) << r.err;
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_, run_;
};

TEST_F(RunFolderRender, TheRunKeepsItsReferenceAndRendersAfterTheOriginalMoved) {
  EXPECT_EQ(slurp(run_ / "reference_0.csv"), kReference);
  fs::rename(dir_ / "refs", dir_ / "moved");
  const CommandResult r =
      runCosim("render " + run_.string() + " --out " + (dir_ / "frame.png").string() + " --quiet");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "frame.png"));
}

TEST_F(RunFolderRender, ADefectInTheRunsScenarioNamesTheRunsFileAndLine) {
  std::string yaml = slurp(run_ / "scenario.yaml");
  const auto at = yaml.find("model: cf2");
  ASSERT_NE(at, std::string::npos) << yaml;
  yaml.replace(at, 10, "model: blimp");
  std::ofstream(run_ / "scenario.yaml") << yaml;
  int line = 1;
  for (std::size_t i = 0; i < at; ++i) line += yaml[i] == '\n';
  const CommandResult r =
      runCosim("render " + run_.string() + " --out " + (dir_ / "frame.png").string() + " --quiet");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("cosim: " + (run_ / "scenario.yaml").string() + ": line " +
                       std::to_string(line) + ", key vehicles[0].model: no model 'blimp'"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find((dir_ / "s.yaml").string()), std::string::npos) << r.err;
}

}  // namespace
