#pragma once
// Output files appear complete or not at all (CONTRACT.md), also after a crash or a power cut: a
// file is written under a temporary name beside its target (core/temporary_name.h), flushed to
// the disk (fsync), renamed over the target, and then its folder is flushed too, so that the
// rename itself is on the disk (without that, a power cut can leave the old file or none).
#include <filesystem>
#include <string>

namespace cosim {

// Writes `content` to `path` that way. Throws std::runtime_error naming `path` on failure (full
// disk, a missing or unwritable folder); no temporary file is left behind then.
void writeFileAtomically(const std::filesystem::path& path, const std::string& content);

// The end of the same protocol for an output written by another program (ffmpeg, gnuplot) under
// a temporary name: flushes `written` to the disk (a folder, e.g. of PNG frames: every file in it
// and the folder itself), renames it to `target` and flushes target's folder. An existing folder
// at `target` is removed first (rename cannot replace a folder that is not empty). On failure
// `written` is removed and std::runtime_error naming `target` is thrown.
void moveIntoPlace(const std::filesystem::path& written, const std::filesystem::path& target);

}  // namespace cosim
