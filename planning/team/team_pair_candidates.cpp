#include "planning/team/team_pair_candidates.h"

#include <algorithm>
#include <cmath>

namespace cosim {

namespace {

// A cell's three integer coordinates in one key (21 bits each, offset to stay non-negative:
// rooms up to a million cells a side).
std::uint64_t cellKey(long x, long y, long z) {
  constexpr long kOffset = 1L << 20;
  const auto u = [](long v) { return static_cast<std::uint64_t>(v + kOffset) & 0x1fffff; };
  return (u(x) << 42) | (u(y) << 21) | u(z);
}

}  // namespace

std::vector<std::pair<int, int>> candidatePairs(
    const std::vector<std::vector<Eigen::Vector3d>>& samples, long first, long last,
    const Eigen::Vector3d& scale, double reach) {
  // (cell, agent) entries sorted by cell: the agents of a cell are then adjacent, in increasing
  // order (one sort instead of a hash map of vectors: no allocation per cell).
  std::vector<std::pair<std::uint64_t, int>> entries;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY);
    Eigen::Vector3d hi = -lo;
    for (long s = first; s <= last; ++s) {
      const Eigen::Vector3d p = samples[i][s].cwiseProduct(scale);
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    const auto cell = [&](double v) { return static_cast<long>(std::floor(v / reach)); };
    const double grow = 0.5 * reach;
    for (long x = cell(lo.x() - grow); x <= cell(hi.x() + grow); ++x)
      for (long y = cell(lo.y() - grow); y <= cell(hi.y() + grow); ++y)
        for (long z = cell(lo.z() - grow); z <= cell(hi.z() + grow); ++z)
          entries.emplace_back(cellKey(x, y, z), static_cast<int>(i));
  }
  std::sort(entries.begin(), entries.end());
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t a = 0; a < entries.size();) {
    std::size_t b = a;
    while (b < entries.size() && entries[b].first == entries[a].first) ++b;
    for (std::size_t i = a; i < b; ++i)
      for (std::size_t j = i + 1; j < b; ++j)
        pairs.emplace_back(entries[i].second, entries[j].second);
    a = b;
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace cosim
