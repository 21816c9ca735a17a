#pragma once
// Reading back JSON that cosim wrote (a run's run.json, a sweep job's result.json and
// metrics.json) as the input it then is: a file that is missing, too large or not JSON is an
// InputError naming the file and, for bad JSON, the line and column.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

namespace cosim {

// The files are small (a 20-robot team's metrics.json is tens of kilobytes); anything larger
// than this is not one of them.
constexpr std::uintmax_t kMaxJsonFileBytes = 64u << 20;

// Parses `text`, read from `file` (named in errors). Throws InputError(file, "line L, column C",
// problem) if it is not JSON.
nlohmann::ordered_json parseJsonText(const std::string& text, const std::string& file);

// Reads `file` (a regular file of at most kMaxJsonFileBytes) and parses it; InputError if not.
nlohmann::ordered_json readJsonFile(const std::filesystem::path& file);

}  // namespace cosim
