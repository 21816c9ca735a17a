#pragma once
// The output folders of the commands: made before work starts, checked before anything is
// computed, and cleared of an earlier command's results. The files in them are written with
// core/atomic_file.h.
#include <filesystem>
#include <string>
#include <vector>

#include "core/csv_text.h"     // csvField, for the CSV files the commands write

namespace cosim {

// Creates `dir` (and parents) if needed; throws InputError if it exists as a file or cannot be
// created. An empty `dir` makes a new time-stamped folder under out/<prefix>-...
std::filesystem::path prepareOutputDir(const std::string& dir, const std::string& prefix);

// Checks, before any work, that prepareOutputDir(dir) will succeed, without creating anything:
// `dir` is a writable folder, or the nearest part of it that exists is one. Throws InputError
// as prepareOutputDir does. An empty `dir` (a new folder under out/) passes.
void checkOutputDir(const std::string& dir);

// Checks, before any work, that a file (or, with `folder`, a folder of frames) can be written at
// `path`: its parent folder exists and is writable, its name fits the file system (255 bytes)
// and it is not an existing folder (a file), or not an existing file (a folder), nor a FIFO, a
// device or a socket (core/atomic_file.h would replace it: never done). Throws
// InputError(path, option, problem).
void checkOutputPath(const std::filesystem::path& path, const std::string& option,
                     bool folder = false);

// Removes what an earlier command left in `dir` under these names (a name may end in '*': every
// entry starting with the rest), files and folders alike, so that a command stopped early or
// refused cannot leave an older result looking like its own. Missing names are fine.
void removeStaleResults(const std::filesystem::path& dir, const std::vector<std::string>& names);

}  // namespace cosim
