#include "core/json_reading.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "core/input_file.h"

namespace cosim {

namespace {

// "line L, column C" of the character at 0-based `offset` in `text` (columns count bytes).
std::string linePlace(const std::string& text, std::size_t offset) {
  offset = std::min(offset, text.size());
  const auto begin = text.begin(), at = begin + static_cast<std::ptrdiff_t>(offset);
  const std::size_t line = 1 + static_cast<std::size_t>(std::count(begin, at, '\n'));
  const std::size_t line_start = text.rfind('\n', offset == 0 ? 0 : offset - 1);
  const std::size_t column =
      (line_start == std::string::npos || offset == 0) ? offset + 1 : offset - line_start;
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// nlohmann's message without its "[json.exception.parse_error.101] parse error at line L,
// column C: " preamble (the place is given separately).
std::string parseProblem(const std::string& what) {
  const std::size_t at = what.find("syntax error");
  return "not valid JSON: " + (at == std::string::npos ? what : what.substr(at));
}

}  // namespace

nlohmann::ordered_json parseJsonText(const std::string& text, const std::string& file) {
  try {
    return nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::ordered_json::parse_error& e) {
    // e.byte counts the characters read, the offending one included.
    throw InputError(file, linePlace(text, e.byte == 0 ? 0 : e.byte - 1), parseProblem(e.what()));
  }
}

nlohmann::ordered_json readJsonFile(const std::filesystem::path& file) {
  return parseJsonText(readInputFile(file.string(), kMaxJsonFileBytes, "JSON file"), file.string());
}

}  // namespace cosim
