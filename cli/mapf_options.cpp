#include "cli/mapf_options.h"

#include "cli/option_checks.h"
#include "core/input_error.h"
#include "planning/mapf/mapf_problem.h"

namespace cosim::cli {

namespace {

int parseCount(const std::string& text, const std::string& whole) {
  std::size_t used = 0;
  long v = 0;
  try {
    v = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || v < 1 || v > 1'000'000)
    throw InputError("command line", "--agents " + whole,
                     "expected N or START:STOP:STEP with whole numbers from 1 to 1000000");
  return static_cast<int>(v);
}

}  // namespace

std::vector<std::string> MapfArgs::plannerSets() const {
  std::vector<std::string> all = sets;
  if (window > 0) all.push_back("window=" + std::to_string(window));
  return all;
}

std::vector<int> parseAgentCounts(const std::string& text) {
  const auto first = text.find(':');
  if (first == std::string::npos) return {parseCount(text, text)};
  const auto second = text.find(':', first + 1);
  if (second == std::string::npos || text.find(':', second + 1) != std::string::npos)
    throw InputError("command line", "--agents " + text, "expected N or START:STOP:STEP");
  const int start = parseCount(text.substr(0, first), text);
  const int stop = parseCount(text.substr(first + 1, second - first - 1), text);
  const int step = parseCount(text.substr(second + 1), text);
  if (stop < start) throw InputError("command line", "--agents " + text, "STOP is below START");
  if ((stop - start) / step >= 10000)
    throw InputError("command line", "--agents " + text, "more than 10000 agent counts");
  std::vector<int> counts;
  for (int n = start; n <= stop; n += step) counts.push_back(n);
  return counts;
}

// Seed 004 §5.1: obstacles set by the user.
Cell parseBlockCell(const std::string& text) {
  const auto comma = text.find(',');
  try {
    if (comma != std::string::npos) {
      std::size_t used_x = 0, used_y = 0;
      const int x = std::stoi(text.substr(0, comma), &used_x);
      const int y = std::stoi(text.substr(comma + 1), &used_y);
      if (used_x == comma && used_y == text.size() - comma - 1) return {x, y, 0};
    }
  } catch (const std::exception&) {
  }
  throw InputError("command line", "--block " + text, "expected X,Y (column,row)");
}

std::vector<std::string> splitPlannerList(const std::string& text) {
  std::vector<std::string> names;
  std::size_t from = 0;
  for (;;) {
    const auto comma = text.find(',', from);
    const std::string name = text.substr(from, comma == std::string::npos ? comma : comma - from);
    if (name.empty())
      throw InputError("command line", "--planner " + text, "empty planner name in the list");
    names.push_back(name);
    if (comma == std::string::npos) return names;
    from = comma + 1;
  }
}

CLI::Validator agentCountOrRange() {
  const CLI::Validator count = wholeNumberIn(1, kMaxMapfAgents);
  return CLI::Validator(
      [count](std::string& input) -> std::string {
        if (input.find(':') != std::string::npos) return "";
        std::string copy = input;
        return count(copy);
      },
      "N or START:STOP:STEP");
}

}  // namespace cosim::cli
