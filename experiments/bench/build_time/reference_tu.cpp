// The yardstick of experiments/bench/build_time/measure_build_time.sh: a translation unit whose
// cost depends only on the compiler and the machine, never on cosim's code. The script compiles it
// with the project's Release flags in the same run as the build it measures and reports the
// build's CPU seconds as a multiple of this file's, so that two runs on a loaded or different
// machine compare. It is not part of any target. Keep this file unchanged: editing it changes
// the unit every earlier ratio was measured in.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

namespace {

struct Cell {
  int x = 0;
  int y = 0;
  bool operator<(const Cell& other) const { return x != other.x ? x < other.x : y < other.y; }
};

// A little of everything the headers above declare, instantiated so the optimiser has work.
std::map<Cell, double> distances(const std::vector<Cell>& cells) {
  std::map<Cell, double> out;
  for (const Cell& c : cells) out[c] = std::hypot(double(c.x), double(c.y));
  return out;
}

std::string describe(const std::variant<int, double, std::string>& value) {
  std::ostringstream text;
  std::visit([&text](const auto& v) { text << v; }, value);
  return text.str();
}

}  // namespace

int main() {
  std::vector<Cell> cells;
  for (int i = 0; i < 10; ++i) cells.push_back({i, 10 - i});
  std::sort(cells.begin(), cells.end());
  const auto d = distances(cells);
  std::unordered_map<std::string, std::function<double(double)>> ops{
      {"sqrt", [](double v) { return std::sqrt(v); }}, {"sq", [](double v) { return v * v; }}};
  std::array<double, 3> sums{};
  for (const auto& [cell, dist] : d) sums[std::size_t(cell.x) % 3] += ops.at("sq")(dist);
  auto owner = std::make_unique<std::optional<double>>(std::accumulate(sums.begin(), sums.end(), 0.0));
  std::cout << describe(owner->value_or(0.0)) << ' ' << describe(std::string("cells")) << '\n';
  return 0;
}
