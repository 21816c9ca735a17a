#include "planning/mapf/spatial_astar.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>

namespace cosim {

SpatialAStarResult spatialAStar(const MapfGrid& grid, const SpatialAStarRequest& r) {
  SpatialAStarResult out;
  const auto isBlocked = [&](int c) {
    return !grid.free(c) || (r.extra_blocked && (*r.extra_blocked)[c] && c != r.start);
  };
  if (isBlocked(r.goal) || !grid.free(r.start)) return out;  // the seed returns at once
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto heuristic = [&](int c) {
    const double h = grid.lowerBound(c, r.goal);
    return r.noise > 0.0 ? h + r.noise * unit(*r.rng) : h;
  };
  std::vector<int> g(grid.cellCount(), std::numeric_limits<int>::max());
  std::vector<int> parent(grid.cellCount(), -1);
  std::vector<double> h_of(grid.cellCount(), -1.0);  // noise drawn once per cell
  // (f, -g, cell)
  using Entry = std::tuple<double, int, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  g[r.start] = 0;
  h_of[r.start] = heuristic(r.start);
  open.emplace(h_of[r.start], 0, r.start);
  while (!open.empty()) {
    const auto [f, minus_g, c] = open.top();
    open.pop();
    (void)f;
    if (-minus_g > g[c]) continue;  // stale
    if (c == r.goal) {
      for (int x = c; x != -1; x = parent[x]) out.cells.push_back(x);
      std::reverse(out.cells.begin(), out.cells.end());
      return out;
    }
    if ((++out.expansions & 1023) == 0 && r.deadline && r.deadline->expired()) return out;
    for (const int n : grid.neighbours(c)) {
      if (isBlocked(n) || g[c] + 1 >= g[n]) continue;  // a better g re-opens n (seed's rule)
      g[n] = g[c] + 1;
      parent[n] = c;
      if (h_of[n] < 0) h_of[n] = heuristic(n);
      open.emplace(g[n] + h_of[n], -g[n], n);
    }
  }
  return out;
}

}  // namespace cosim
