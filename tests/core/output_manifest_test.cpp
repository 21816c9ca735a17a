// Output folders as a database treats its files (core/output_manifest.h): a file is deleted or
// replaced only if the folder's .cosim-manifest (or this process's own record) proves cosim wrote
// it as it is now; temporary files never follow or truncate what is already at their name
// (core/temporary_name.h).
#include "core/output_manifest.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/temporary_name.h"
#include "tests/support/test_files.h"

using namespace cosim;
using cosim::test::makeFreshDir;
using cosim::test::slurp;
namespace fs = std::filesystem;

namespace {

// Runs `write` in a child process, which then ends: what it wrote is proven to this process
// only by the manifest it left (this process's ledger never saw those files).
void inAnotherProcess(const std::function<void()>& write) {
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    try {
      write();
    } catch (...) {
      ::_exit(1);
    }
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

}  // namespace

TEST(OutputManifest, AnotherRunsManifestProvesItsFilesUntilOneChanges) {
  const fs::path dir = makeFreshDir("manifest-proves");
  inAnotherProcess([&] {
    fs::create_directories(dir / "figures");
    writeFileAtomically(dir / "metrics.json", "{\"a\": 1}\n");
    writeFileAtomically(dir / "figures" / "top.svg", "<svg/>");
    writeOutputManifest(dir, "run", "complete");
  });
  const nlohmann::json m = nlohmann::json::parse(slurp(dir / kOutputManifestName));
  EXPECT_EQ(m["state"], "complete");
  EXPECT_EQ(m["files"]["metrics.json"]["size"], 9);
  EXPECT_EQ(m["files"]["figures/top.svg"]["size"], 6);
  EXPECT_EQ(outputManifestState(dir), "complete");
  EXPECT_TRUE(provenCosimOutput(dir / "metrics.json"));
  EXPECT_TRUE(provenCosimOutput(dir / "figures" / "top.svg"));
  EXPECT_TRUE(firstUnprovenOutput(dir / "figures").empty());

  // Same size, other bytes: the CRC-32 tells.
  std::ofstream(dir / "metrics.json") << "{\"a\": 2}\n";
  EXPECT_FALSE(provenCosimOutput(dir / "metrics.json"));
  std::ofstream(dir / "figures" / "mine.txt") << "notes";
  EXPECT_EQ(firstUnprovenOutput(dir / "figures"), dir / "figures" / "mine.txt");
  fs::remove_all(dir);
}

TEST(OutputManifest, RemovingStaleResultsRefusesAndRemovesNothingIfOneIsNotProven) {
  const fs::path dir = makeFreshDir("manifest-refuses");
  inAnotherProcess([&] {
    writeFileAtomically(dir / "plan.json", "{}\n");
    writeFileAtomically(dir / "path.csv", "x,y,z\n");
    writeOutputManifest(dir, "plan", "complete");
  });
  std::ofstream(dir / "path.csv") << "x,y,z\n1,2,3\n";  // changed by the user since
  try {
    removeStaleResults(dir, {"plan.json", "path.csv"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir / "path.csv").string());
    EXPECT_EQ(e.place(), "--out");
  }
  EXPECT_TRUE(fs::exists(dir / "plan.json"));  // checked all before removing any
  EXPECT_EQ(slurp(dir / "path.csv"), "x,y,z\n1,2,3\n");
  std::ofstream(dir / "path.csv") << "x,y,z\n";  // as cosim wrote it again: proven
  removeStaleResults(dir, {"plan.json", "path.csv"});
  EXPECT_FALSE(fs::exists(dir / "plan.json"));
  EXPECT_FALSE(fs::exists(dir / "path.csv"));
  fs::remove_all(dir);
}

TEST(OutputManifest, ASymbolicLinkOrADamagedManifestProvesNothing) {
  const fs::path dir = makeFreshDir("manifest-link");
  inAnotherProcess([&] {
    writeFileAtomically(dir / "index.html", "<html/>");
    writeOutputManifest(dir, "run", "complete");
  });
  const fs::path outside = makeFreshDir("manifest-link-target") / "precious.txt";
  std::ofstream(outside) << "keep";
  fs::remove(dir / "index.html");
  fs::create_symlink(outside, dir / "index.html");
  EXPECT_FALSE(provenCosimOutput(dir / "index.html"));
  EXPECT_THROW(writeFileAtomically(dir / "index.html", "<html/>"), InputError);
  EXPECT_EQ(slurp(outside), "keep");
  fs::remove(dir / "index.html");

  inAnotherProcess([&] {
    writeFileAtomically(dir / "index.html", "<html/>");
    writeOutputManifest(dir, "run", "complete");
  });
  std::ofstream(dir / kOutputManifestName) << "{ not json";
  EXPECT_FALSE(provenCosimOutput(dir / "index.html"));
  EXPECT_EQ(outputManifestState(dir), "");
  EXPECT_THROW(writeOutputManifest(dir, "run"), InputError);  // not cosim's to replace
  fs::remove_all(dir);
  fs::remove_all(outside.parent_path());
}

TEST(OutputManifest, AFolderCosimWroteNothingIntoGetsNoManifest) {
  const fs::path dir = makeFreshDir("manifest-none");
  std::ofstream(dir / "notes.txt") << "mine";
  writeOutputManifest(dir, "run", "unfinished");
  EXPECT_FALSE(fs::exists(dir / kOutputManifestName));
  fs::remove_all(dir);
}

TEST(OutputManifest, AnEarlierManifestsEntriesAreKeptWhenAnotherCommandAddsItsFiles) {
  const fs::path dir = makeFreshDir("manifest-merge");
  inAnotherProcess([&] {
    writeFileAtomically(dir / "metrics.json", "{}\n");
    writeOutputManifest(dir, "run", "complete");
  });
  inAnotherProcess([&] {
    writeFileAtomically(dir / "compare.json", "{}\n");
    writeOutputManifest(dir, "compare-real", "complete");
  });
  const nlohmann::json m = nlohmann::json::parse(slurp(dir / kOutputManifestName));
  EXPECT_EQ(m["files"].size(), 2u);
  EXPECT_EQ(m["command"], "compare-real");
  EXPECT_TRUE(provenCosimOutput(dir / "metrics.json"));
  EXPECT_TRUE(provenCosimOutput(dir / "compare.json"));
  fs::remove_all(dir);
}

// A symbolic link planted at the temporary name (".metrics.json.tmp<pid>") pointing outside the
// folder: the write neither follows nor truncates it; it takes the next name.
TEST(TemporaryName, APlantedLinkAtTheTemporaryNameLeavesItsTargetUnchanged) {
  const fs::path dir = makeFreshDir("tmp-link");
  const fs::path outside = makeFreshDir("tmp-link-target") / "passwd";
  std::ofstream(outside) << "root:x:0:0\n";
  const fs::path planted = temporaryNameFor(dir / "metrics.json", ".tmp");
  fs::create_symlink(outside, planted);
  writeFileAtomically(dir / "metrics.json", "{}\n");
  EXPECT_EQ(slurp(outside), "root:x:0:0\n");
  EXPECT_EQ(slurp(dir / "metrics.json"), "{}\n");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(planted)));  // not removed either

  // A file there is neither truncated nor removed; a folder made beside it takes the next name.
  const fs::path left = temporaryNameFor(dir / "video.mp4", ".part");
  std::ofstream(left) << "someone's";
  const fs::path work = createTemporaryFolder(dir / "video.mp4", ".part");
  EXPECT_NE(work, left);
  EXPECT_TRUE(fs::is_directory(work));
  EXPECT_EQ(slurp(left), "someone's");
  const TemporaryFile f = createTemporaryFile(dir / "video.mp4", ".part");
  ::close(f.fd);
  EXPECT_NE(f.path, left);
  EXPECT_NE(f.path, work);
  fs::remove_all(dir);
  fs::remove_all(outside.parent_path());
}

TEST(OutputFiles, AnOutputNameLongerThanAFileSystemAllowsIsBadInput) {
  const std::string long_name(300, 'a');
  try {
    checkOutputDir("/tmp/" + long_name + "/run");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "--out");
    EXPECT_NE(e.problem().find("300 bytes, more than the 255"), std::string::npos) << e.what();
  }
}
