#pragma once
// Output files appear complete or not at all (CONTRACT.md): everything is written to a
// temporary name in the same folder and renamed into place.
#include <filesystem>
#include <string>

namespace cosim {

// Writes `content` to `path` atomically (temporary file + fsync + rename). Throws
// std::runtime_error naming the path on failure (full disk, unwritable folder).
void writeFileAtomically(const std::filesystem::path& path, const std::string& content);

// Creates `dir` (and parents) if needed; throws InputError if it exists as a file or cannot be
// created. An empty `dir` makes a new time-stamped folder under out/<prefix>-...
std::filesystem::path prepareOutputDir(const std::string& dir, const std::string& prefix);

// Quotes a CSV field if it contains a comma, quote or newline.
std::string csvField(const std::string& s);

}  // namespace cosim
