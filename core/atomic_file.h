#pragma once
// Output files appear complete or not at all, also after a crash or a power cut: a
// file is written under a temporary name beside its target (core/temporary_name.h), flushed to
// the disk (fsync), renamed over the target, and then its folder is flushed too, so that the
// rename itself is on the disk (without that, a power cut can leave the old file or none).
#include <filesystem>
#include <string>

namespace cosim {

// Writes `content` to `path` that way. Throws std::runtime_error naming `path` on failure (full
// disk, a missing or unwritable folder); no temporary file is left behind then. An existing
// FIFO, device or socket at `path` is never replaced (the rename would put a regular file in
// place of /dev/null): InputError (core/input_error.h) before anything is written.
void writeFileAtomically(const std::filesystem::path& path, const std::string& content);

// The end of the same protocol for an output written by another program (ffmpeg, gnuplot) under
// a temporary name: flushes `written` to the disk (a folder, e.g. of PNG frames: every file in it
// and the folder itself), renames it to `target` and flushes target's folder. An existing folder
// at `target` is removed first (rename cannot replace a folder that is not empty). On failure
// `written` is removed and std::runtime_error naming `target` is thrown; InputError, as above,
// for a FIFO, device or socket at `target`.
void moveIntoPlace(const std::filesystem::path& written, const std::filesystem::path& target);

// What `path` is if it exists and is neither a regular file, a folder nor a symbolic link
// ("a FIFO", "a character device", "a block device", "a socket"); "" otherwise. A symbolic link
// is renamed over as a file is (what it points to stays).
std::string specialFileKind(const std::filesystem::path& path);

// The problem of an output path naming such a file, for InputError messages.
std::string notRegularProblem(const std::string& kind);

}  // namespace cosim
