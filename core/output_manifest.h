#pragma once
// What cosim wrote into an output folder, so that it never deletes or replaces a file it did not
// write. Every file cosim puts in place (core/atomic_file.h: writeFileAtomically, moveIntoPlace)
// is recorded in this process's ledger with its size and CRC-32; a command ends by writing the
// ledger's files under its output folder, merged with the folder's earlier record, into
// FOLDER/.cosim-manifest (JSON, written atomically, LAST). A later command may delete or replace
// an existing file only if it is proven cosim's: its present size and CRC-32 equal those recorded
// for it by this process or by the manifest of a folder holding it (the nearest one listing it).
// A file changed since, a file of the user's, a symbolic link, or a manifest that cannot be read
// proves nothing: the command is refused (InputError, exit 2) naming that file.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace cosim {

inline constexpr const char* kOutputManifestName = ".cosim-manifest";

// Records the regular file (or every regular file in the folder) now at `path` as written by this
// process. Called by core/atomic_file.h once a file is in place.
void recordWrittenOutput(const std::filesystem::path& path);
// The same for a file whose bytes were just written: no need to read them again.
void recordWrittenOutput(const std::filesystem::path& path, std::uintmax_t size, std::uint32_t crc);

// Whether the regular file at `path` is proven cosim's (see above). A missing file is not; a
// manifest is if it is one cosim wrote.
bool provenCosimOutput(const std::filesystem::path& path);

// The first file (or symbolic link, FIFO, ...) at or under `path` that is not proven cosim's;
// empty if there is none (a missing `path` included). Folders are looked into, not judged.
std::filesystem::path firstUnprovenOutput(const std::filesystem::path& path);

// The problem of a file that is not proven cosim's, for InputError messages naming it.
std::string unprovenOutputProblem();

// Throws InputError(the first file not proven cosim's, option, unprovenOutputProblem()) if
// anything at or under `path` is not proven cosim's; a missing `path` passes.
void requireCosimOutput(const std::filesystem::path& path, const std::string& option);

// The entries of `dir` that `names` name (a name may hold one '*': every entry starting with the
// text before it and ending with the text after it, "frames_*", "video*.mp4"); missing names are
// left out.
std::vector<std::filesystem::path> matchingOutputs(const std::filesystem::path& dir,
                                                   const std::vector<std::string>& names);

// Merges into dir/.cosim-manifest the files this process wrote under `dir` (replacing earlier
// entries of those names) and keeps the earlier entries whose files are still as recorded;
// `state` says what the folder holds ("complete", "unfinished", "partial: 2 of 8 jobs"),
// `command` which command wrote it. Serialized against other writers of the same manifest
// (flock on the folder). Throws std::runtime_error if the manifest cannot be written.
void writeOutputManifest(const std::filesystem::path& dir, const std::string& command,
                         const std::string& state = "complete");

// For a command whose output is one file (or one folder of frames) named by the user: records it
// in the manifest of the folder holding it, so that a later command may replace it.
void writeOutputManifestOf(const std::filesystem::path& output, const std::string& command);

// The state the manifest of `dir` records ("" if it has none or it cannot be read).
std::string outputManifestState(const std::filesystem::path& dir);

// Writes the manifest of a command's output folder when it goes out of scope, whatever way the
// command ends: with the state given to finish(), else "unfinished" (an exception, an early
// return). The files written before a failure are then still proven cosim's for the next run.
class OutputManifestScope {
 public:
  OutputManifestScope(std::filesystem::path dir, std::string command)
      : dir_(std::move(dir)), command_(std::move(command)) {}
  OutputManifestScope(const OutputManifestScope&) = delete;
  OutputManifestScope& operator=(const OutputManifestScope&) = delete;
  ~OutputManifestScope();

  // Writes the manifest now with `state` (throws as writeOutputManifest does).
  void finish(const std::string& state = "complete");
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
  std::string command_;
  bool written_ = false;
};

}  // namespace cosim
