// Atomic writes: the target has the old content or the new, never a part, and no temporary file
// is left beside it; a FIFO or a device is never replaced.
#include "core/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "core/input_error.h"
#include "core/temporary_name.h"
#include "tests/support/test_files.h"

using namespace cosim;
using cosim::test::makeFreshDir;
using cosim::test::slurp;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST(AtomicFile, WriteLeavesOnlyTheTarget) {
  const fs::path dir = makeFreshDir("write");
  writeFileAtomically(dir / "metrics.json", "{}\n");
  EXPECT_EQ(slurp(dir / "metrics.json"), "{}\n");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"metrics.json"});
  fs::remove_all(dir);
}

TEST(AtomicFile, WriteReplacesAFileItWrote) {
  const fs::path dir = makeFreshDir("replace");
  writeFileAtomically(dir / "a.csv", "an older and longer content\n");
  writeFileAtomically(dir / "a.csv", "new\n");
  EXPECT_EQ(slurp(dir / "a.csv"), "new\n");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"a.csv"});
  fs::remove_all(dir);
}

// core/output_manifest.h: a file cosim cannot prove it wrote is never replaced.
TEST(AtomicFile, AUsersFileIsNeitherReplacedNorRenamedOver) {
  const fs::path dir = makeFreshDir("users-file");
  std::ofstream(dir / "a.csv") << "the user's\n";
  try {
    writeFileAtomically(dir / "a.csv", "new\n");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not written by cosim, or changed since"), std::string::npos)
        << e.what();
  }
  std::ofstream(dir / ".a.csv.part1") << "moved";
  EXPECT_THROW(moveIntoPlace(dir / ".a.csv.part1", dir / "a.csv"), InputError);
  EXPECT_EQ(slurp(dir / "a.csv"), "the user's\n");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"a.csv"});  // no temporary file left
  fs::remove_all(dir);
}

TEST(AtomicFile, WriteIntoAMissingFolderThrowsNamingThePath) {
  const fs::path dir = makeFreshDir("missing");
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
  const fs::path dir = makeFreshDir("move");
  const fs::path target = dir / "final.png", tmp = temporaryNameFor(target, ".part");
  writeFileAtomically(target, "old");
  std::ofstream(tmp) << "png bytes";
  moveIntoPlace(tmp, target);
  EXPECT_EQ(slurp(target), "png bytes");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"final.png"});
  fs::remove_all(dir);
}

TEST(AtomicFile, MoveIntoPlaceReplacesAFolderOfFramesItWrote) {
  const fs::path dir = makeFreshDir("frames");
  const fs::path target = dir / "frames_chase", tmp = temporaryNameFor(target, ".part");
  fs::create_directories(tmp);
  std::ofstream(tmp / "00009.png") << "stale";
  moveIntoPlace(tmp, target);
  fs::create_directories(tmp);
  std::ofstream(tmp / "00001.png") << "frame 1";
  moveIntoPlace(tmp, target);
  EXPECT_EQ(entries(target), std::vector<std::string>{"00001.png"});
  EXPECT_EQ(entries(dir), std::vector<std::string>{"frames_chase"});
  fs::remove_all(dir);
}

TEST(AtomicFile, MoveIntoPlaceKeepsAFolderHoldingAFileCosimDidNotWrite) {
  const fs::path dir = makeFreshDir("frames-users");
  const fs::path target = dir / "frames_chase", tmp = temporaryNameFor(target, ".part");
  fs::create_directories(target);
  std::ofstream(target / "holiday.jpg") << "the user's";
  fs::create_directories(tmp);
  std::ofstream(tmp / "00001.png") << "frame 1";
  try {
    moveIntoPlace(tmp, target);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find((target / "holiday.jpg").string()), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(slurp(target / "holiday.jpg"), "the user's");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"frames_chase"});  // the frames went
  fs::remove_all(dir);
}

TEST(AtomicFile, MoveIntoPlaceThatFailsRemovesWhatWasWritten) {
  const fs::path dir = makeFreshDir("move-fail");
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

// The rename would put a regular file in place of a FIFO or a device (as root it replaced the
// machine's /dev/null): such a target is refused, untouched, with nothing left beside it.
TEST(AtomicFile, AFifoOrADeviceIsNeverReplaced) {
  const fs::path dir = makeFreshDir("special");
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  try {
    writeFileAtomically(fifo, "data");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              fifo.string() +
                  ": is a FIFO, not a regular file: cosim writes its outputs as new "
                  "regular files and would replace it; name a file instead");
  }
  std::ofstream(dir / ".frames.part") << "frame";
  EXPECT_THROW(moveIntoPlace(dir / ".frames.part", fifo), InputError);
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  EXPECT_EQ(entries(dir), std::vector<std::string>{"pipe"});  // no temporary file beside it
  EXPECT_EQ(specialFileKind(fifo), "a FIFO");
  EXPECT_EQ(specialFileKind(dir), "");
  EXPECT_EQ(specialFileKind(dir / "missing"), "");
  // A character device of our own like /dev/null (the real one is never written to), where
  // this process may make one (root with CAP_MKNOD).
  const fs::path device = dir / "null";
  if (::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0) {
    EXPECT_THROW(writeFileAtomically(device, "data"), InputError);
    EXPECT_TRUE(fs::is_character_file(fs::symlink_status(device)));
  }
  fs::remove_all(dir);
}
