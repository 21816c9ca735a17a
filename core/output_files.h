#pragma once
// The output folders of the commands: made before work starts, checked before anything is
// computed, and cleared of an earlier command's results (only those core/output_manifest.h proves
// cosim's). The files in them are written with core/atomic_file.h.
#include <filesystem>
#include <string>
#include <vector>

#include "core/csv_text.h"  // csvField, for the CSV files the commands write

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
// device or a socket (core/atomic_file.h would replace it: never done), nor anything cosim
// cannot prove it wrote (core/output_manifest.h: a user's file, a file changed since, a folder
// holding such a file). Throws InputError(path, option, problem).
void checkOutputPath(const std::filesystem::path& path, const std::string& option,
                     bool folder = false);

// Throws InputError(path, option, ...) if a part of `path` is longer than the 255 bytes a file
// system allows in a name.
void checkNameLengths(const std::filesystem::path& path, const std::string& option);

// Removes what an earlier command left in `dir` under these names (a name may hold one '*', as
// core/output_manifest.h's matchingOutputs reads it), files and folders alike, so that a command
// stopped early cannot leave an older result looking like its own. Called once the command's inputs
// are checked. Missing names are fine. Only files cosim can prove it wrote (core/output_manifest.h)
// are removed: if any entry is, or holds, anything else, InputError(that entry, option, ...) names
// it and nothing is removed.
void removeStaleResults(const std::filesystem::path& dir, const std::vector<std::string>& names,
                        const std::string& option = "--out");

}  // namespace cosim
