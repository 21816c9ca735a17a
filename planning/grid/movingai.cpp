#include "planning/grid/movingai.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>

#include "core/input_error.h"
#include "core/input_file.h"

namespace cosim {

namespace {

// Splits into lines, dropping a trailing '\r' (some benchmark files use CRLF). Views into the
// text, not copies: the largest map is 256 MB of rows.
std::vector<std::string_view> splitLines(const std::string& text) {
  std::vector<std::string_view> lines;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    begin = end + 1;
  }
  return lines;
}

std::string lineRef(std::size_t index) { return "line " + std::to_string(index + 1); }

// Parses "<key> <integer>" from a header line.
int headerValue(const std::vector<std::string_view>& lines, std::size_t i, const std::string& key,
                const std::string& file) {
  if (i >= lines.size()) throw InputError(file, lineRef(i), "missing '" + key + "' header");
  std::istringstream in{std::string(lines[i])};
  std::string word;
  long value = 0;
  if (!(in >> word) || word != key || !(in >> value))
    throw InputError(file, lineRef(i),
                     "expected '" + key + " <number>', got '" + std::string(lines[i]) + "'");
  if (value <= 0 || value > 1000000)
    throw InputError(file, lineRef(i), key + " must be between 1 and 1000000");
  return static_cast<int>(value);
}

}  // namespace

OccupancyGrid readMovingAIMap(const std::string& path) {
  return parseMovingAIMap(readInputFile(path, kMaxMapFileBytes, "MovingAI map"), path);
}

OccupancyGrid parseMovingAIMap(const std::string& text, const std::string& file) {
  const std::vector<std::string_view> lines = splitLines(text);
  if (lines.empty() || lines[0].substr(0, 4) != "type")
    throw InputError(file, "line 1", "expected 'type octile' header");
  const int height = headerValue(lines, 1, "height", file);
  const int width = headerValue(lines, 2, "width", file);
  if (lines.size() < 4 || lines[3] != "map")
    throw InputError(file, "line 4", "expected 'map'");
  if (std::int64_t(width) * height > OccupancyGrid::kMaxCells)
    throw InputError(file, "line 2", "a " + std::to_string(width) + "x" + std::to_string(height) +
                                         " map exceeds the grid size limit");
  if (lines.size() < 4 + static_cast<std::size_t>(height))
    throw InputError(file, lineRef(lines.size()),
                     "expected " + std::to_string(height) + " map rows, found " +
                         std::to_string(lines.size() - 4));
  OccupancyGrid grid(width, height);
  for (int y = 0; y < height; ++y) {
    const std::string_view row = lines[4 + y];
    if (static_cast<int>(row.size()) != width)
      throw InputError(file, lineRef(4 + y),
                       "row has " + std::to_string(row.size()) + " characters, expected " +
                           std::to_string(width));
    for (int x = 0; x < width; ++x) {
      switch (row[x]) {
        case '.':
        case 'G':
        case 'S':
          break;
        case '@':
        case 'O':
        case 'T':
        case 'W':
          grid.setBlocked(x, y, 0, true);
          break;
        default:
          throw InputError(file, lineRef(4 + y) + ", column " + std::to_string(x + 1),
                           std::string("unknown map character '") + row[x] + "'");
      }
    }
  }
  for (std::size_t i = 4 + height; i < lines.size(); ++i)
    if (!lines[i].empty()) throw InputError(file, lineRef(i), "unexpected text after the map rows");
  return grid;
}

std::vector<MovingAIScenarioLine> readMovingAIScenario(const std::string& path) {
  return parseMovingAIScenario(readInputFile(path, kMaxMapFileBytes, "MovingAI scenario"), path);
}

std::vector<MovingAIScenarioLine> parseMovingAIScenario(const std::string& text,
                                                        const std::string& file) {
  const std::vector<std::string_view> lines = splitLines(text);
  if (lines.empty() || lines[0].substr(0, 7) != "version")
    throw InputError(file, "line 1", "expected 'version 1' header");
  std::vector<MovingAIScenarioLine> out;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].find_first_not_of(" \t") == std::string::npos) continue;
    // Whitespace-separated fields work for both the tab and the older space-separated variant;
    // map names in these files contain no spaces.
    std::istringstream in{std::string(lines[i])};
    MovingAIScenarioLine s;
    s.line = static_cast<int>(i + 1);
    std::string extra, optimal;
    if (!(in >> s.bucket >> s.map >> s.width >> s.height >> s.start_x >> s.start_y >> s.goal_x >>
          s.goal_y >> optimal) ||
        (in >> extra))
      throw InputError(file, lineRef(i),
                       "expected 9 fields: bucket map width height start_x start_y goal_x goal_y "
                       "optimal_length (all but map and optimal_length whole numbers that fit an "
                       "int)");
    char* end = nullptr;
    s.optimal_length = std::strtod(optimal.c_str(), &end);
    if (end == optimal.c_str() || *end != '\0' || !std::isfinite(s.optimal_length))
      throw InputError(file, lineRef(i), "optimal_length '" + optimal + "' is not a number");
    const auto point = optimal.find('.');
    s.optimal_decimals =
        point == std::string::npos ? 0 : static_cast<int>(optimal.size() - point - 1);
    if (s.width <= 0 || s.height <= 0 || s.start_x < 0 || s.start_y < 0 || s.goal_x < 0 ||
        s.goal_y < 0 || s.start_x >= s.width || s.goal_x >= s.width || s.start_y >= s.height ||
        s.goal_y >= s.height || s.optimal_length < 0)
      throw InputError(file, lineRef(i), "coordinates outside the stated map size");
    out.push_back(s);
  }
  return out;
}

bool matchesOptimalLength(const MovingAIScenarioLine& line, double length) {
  const double relative = 1e-4 * std::max(1.0, line.optimal_length);
  const double printed = 0.5 * std::pow(10.0, -line.optimal_decimals) + 1e-12;
  return std::abs(length - line.optimal_length) <= std::max(relative, printed);
}

}  // namespace cosim
