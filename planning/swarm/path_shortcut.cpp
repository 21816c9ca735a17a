#include "planning/swarm/path_shortcut.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace cosim {

namespace {
int sign(int v) {
  return (v > 0) - (v < 0);
}
}  // namespace

PathShortcut::PathShortcut(const OccupancyGrid& grid, const ExtendedNeighbourhood& moves)
    : grid_(grid),
      diagonals_(moves.directions() >= 8),
      sum_(static_cast<std::size_t>(grid.nx() + 1) * (grid.ny() + 1), 0) {
  const int w = grid.nx() + 1;
  for (int y = 0; y < grid.ny(); ++y)
    for (int x = 0; x < grid.nx(); ++x)
      sum_[(y + 1) * w + x + 1] = sum_[y * w + x + 1] + sum_[(y + 1) * w + x] - sum_[y * w + x] +
                                  (grid.blocked(x, y, 0) ? 1 : 0);
}

std::int64_t PathShortcut::blockedIn(int x0, int y0, int x1, int y1) const {
  if (x0 > x1) std::swap(x0, x1);
  if (y0 > y1) std::swap(y0, y1);
  if (x0 < 0 || y0 < 0 || x1 >= grid_.nx() || y1 >= grid_.ny()) return 1;  // outside: blocked
  const int w = grid_.nx() + 1;
  return sum_[(y1 + 1) * w + x1 + 1] - sum_[y0 * w + x1 + 1] - sum_[(y1 + 1) * w + x0] +
         sum_[y0 * w + x0];
}

bool PathShortcut::staircase(const Cell& a, const Cell& b, bool diagonal_first,
                             std::vector<Cell>& out) const {
  const int sx = sign(b.x - a.x), sy = sign(b.y - a.y);
  const int ax = std::abs(b.x - a.x), ay = std::abs(b.y - a.y);
  const int n_diag = diagonals_ ? std::min(ax, ay) : 0;
  const int n_x = ax - n_diag, n_y = ay - n_diag;
  Cell c = a;
  // A straight run is free when the cells it enters are (one rectangle query).
  auto straight = [&](int dx, int dy, int n) {
    if (n == 0) return true;
    if (blockedIn(c.x + dx, c.y + dy, c.x + n * dx, c.y + n * dy) != 0) return false;
    for (int i = 0; i < n; ++i) out.push_back(c = {c.x + dx, c.y + dy, c.z});
    return true;
  };
  // A diagonal move needs its target and both side cells free (no corner cutting).
  auto diagonal = [&](int n) {
    for (int i = 0; i < n; ++i) {
      if (grid_.blocked(c.x + sx, c.y + sy, 0) || grid_.blocked(c.x + sx, c.y, 0) ||
          grid_.blocked(c.x, c.y + sy, 0))
        return false;
      out.push_back(c = {c.x + sx, c.y + sy, c.z});
    }
    return true;
  };
  if (diagonal_first) return diagonal(n_diag) && straight(sx, 0, n_x) && straight(0, sy, n_y);
  return straight(sx, 0, n_x) && straight(0, sy, n_y) && diagonal(n_diag);
}

int PathShortcut::improve(std::vector<Cell>& cells, int window) const {
  int replacements = 0;
  std::vector<double> prefix;
  std::vector<Cell> bridge;
  auto updatePrefix = [&](std::size_t from) {
    prefix.resize(cells.size());
    if (from == 0) prefix[0] = 0.0;
    for (std::size_t k = std::max<std::size_t>(from, 1); k < cells.size(); ++k) {
      const double dx = cells[k].x - cells[k - 1].x, dy = cells[k].y - cells[k - 1].y;
      prefix[k] = prefix[k - 1] + std::sqrt(dx * dx + dy * dy);
    }
  };
  bool changed = true;
  while (changed) {  // sweeps until one finds nothing to replace
    changed = false;
    updatePrefix(0);
    for (std::size_t i = 0; i + 2 < cells.size();) {
      bool replaced = false;
      const std::size_t last = std::min(cells.size() - 1, i + static_cast<std::size_t>(window));
      for (std::size_t j = last; j >= i + 2; --j) {
        const int dx = std::abs(cells[j].x - cells[i].x), dy = std::abs(cells[j].y - cells[i].y);
        const double direct =
            diagonals_ ? std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy) : dx + dy;
        if (direct >= prefix[j] - prefix[i] - 1e-9) continue;
        bool found = false;
        for (const bool diagonal_first : {true, false}) {
          bridge.clear();
          if (staircase(cells[i], cells[j], diagonal_first, bridge)) {
            found = true;
            break;
          }
        }
        if (!found) continue;
        // The bridge ends with cells[j] (and is empty when cells[i] == cells[j], a loop).
        cells.erase(cells.begin() + i + 1, cells.begin() + j + 1);
        cells.insert(cells.begin() + i + 1, bridge.begin(), bridge.end());
        updatePrefix(i + 1);
        ++replacements;
        changed = replaced = true;
        break;
      }
      if (!replaced) ++i;  // else the window from i holds other cells now: scan it again
    }
  }
  return replacements;
}

}  // namespace cosim
