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
// place of /dev/null), nor a file cosim cannot prove it wrote (core/output_manifest.h: a user's
// file, a file changed since, a symbolic link): InputError (core/input_error.h) before anything
// is written. The file written is recorded in the process's ledger of outputs.
void writeFileAtomically(const std::filesystem::path& path, const std::string& content);

// The same without the ownership check and the record: for cosim's own bookkeeping file, the
// output manifest, which core/output_manifest.h checks itself.
void writeBookkeepingFileAtomically(const std::filesystem::path& path, const std::string& content);

// The end of the same protocol for an output written by another program (ffmpeg, gnuplot) under
// a temporary name: flushes `written` to the disk (a folder, e.g. of PNG frames: every file in it
// and the folder itself), renames it to `target` and flushes target's folder. An existing folder
// at `target` is removed first (rename cannot replace a folder that is not empty) only if every
// file in it is proven cosim's; otherwise, as for a file at `target` that is not, `written` is
// removed and InputError names the stranger. On failure `written` is removed and
// std::runtime_error naming `target` is thrown; InputError, as above, for a FIFO, device or
// socket at `target`. What is moved is recorded in the ledger of outputs.
void moveIntoPlace(const std::filesystem::path& written, const std::filesystem::path& target);

// What `path` is if it exists and is neither a regular file, a folder nor a symbolic link
// ("a FIFO", "a character device", "a block device", "a socket"); "" otherwise.
std::string specialFileKind(const std::filesystem::path& path);

// The problem of an output path naming such a file, for InputError messages.
std::string notRegularProblem(const std::string& kind);

}  // namespace cosim
