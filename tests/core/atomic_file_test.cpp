// Atomic writes: the target has the old content or the new, never a part, and no temporary file
// is left beside it.
#include "core/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/temporary_name.h"

using namespace cosim;
namespace fs = std::filesystem;

namespace {

fs::path freshDir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("cosim-core-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST(AtomicFile, WriteLeavesOnlyTheTarget) {
  const fs::path dir = freshDir("write");
  writeFileAtomically(dir / "metrics.json", "{}\n");
  EXPECT_EQ(slurp(dir / "metrics.json"), "{}\n");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"metrics.json"});
  fs::remove_all(dir);
}

TEST(AtomicFile, WriteReplacesAnExistingFile) {
  const fs::path dir = freshDir("replace");
  std::ofstream(dir / "a.csv") << "an older and longer content\n";
  writeFileAtomically(dir / "a.csv", "new\n");
  EXPECT_EQ(slurp(dir / "a.csv"), "new\n");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"a.csv"});
  fs::remove_all(dir);
}

TEST(AtomicFile, WriteIntoAMissingFolderThrowsNamingThePath) {
  const fs::path dir = freshDir("missing");
  const fs::path target = dir / "no-such-folder" / "x.json";
  try {
    writeFileAtomically(target, "{}");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(entries(dir).empty());
  fs::remove_all(dir);
}

TEST(AtomicFile, MoveIntoPlaceRenamesAFileWrittenUnderItsTemporaryName) {
  const fs::path dir = freshDir("move");
  const fs::path target = dir / "final.png", tmp = temporaryNameFor(target, ".part");
  std::ofstream(target) << "old";
  std::ofstream(tmp) << "png bytes";
  moveIntoPlace(tmp, target);
  EXPECT_EQ(slurp(target), "png bytes");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"final.png"});
  fs::remove_all(dir);
}

TEST(AtomicFile, MoveIntoPlaceReplacesAFolderOfFrames) {
  const fs::path dir = freshDir("frames");
  const fs::path target = dir / "frames_chase", tmp = temporaryNameFor(target, ".part");
  fs::create_directories(target);
  std::ofstream(target / "00009.png") << "stale";
  fs::create_directories(tmp);
  std::ofstream(tmp / "00001.png") << "frame 1";
  moveIntoPlace(tmp, target);
  EXPECT_EQ(entries(target), std::vector<std::string>{"00001.png"});
  EXPECT_EQ(entries(dir), std::vector<std::string>{"frames_chase"});
  fs::remove_all(dir);
}

TEST(AtomicFile, MoveIntoPlaceThatFailsRemovesWhatWasWritten) {
  const fs::path dir = freshDir("move-fail");
  const fs::path tmp = dir / ".x.part1";
  std::ofstream(tmp) << "data";
  const fs::path target = dir / "no-such-folder" / "x.mp4";
  try {
    moveIntoPlace(tmp, target);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(entries(dir).empty());
  fs::remove_all(dir);
}
