#include "planning/swarm/ant_path_processing.h"

#include <algorithm>
#include <array>
#include <cstdlib>

namespace cosim {

void AntPathProcessing::removeCycles(std::vector<int>& path) {
  std::size_t n = 0;  // length of the loop-free prefix built in place
  for (std::size_t i = 0; i < path.size(); ++i) {
    const int c = path[i];
    if (position_[c] >= 0) {
      // Back at c: drop the loop c ... path[n-1].
      const std::size_t keep = static_cast<std::size_t>(position_[c]) + 1;
      for (std::size_t j = keep; j < n; ++j) position_[path[j]] = -1;
      n = keep;
      continue;
    }
    position_[c] = static_cast<int>(n);
    path[n++] = c;
  }
  path.resize(n);
  for (int c : path) position_[c] = -1;
}

void AntPathProcessing::smoothLightly(std::vector<int>& path) {
  if (path.size() < 3) return;
  for (std::size_t i = 0; i < path.size(); ++i) position_[path[i]] = static_cast<int>(i);
  std::vector<int> out;
  out.reserve(path.size());
  std::array<int, 8> nb;
  std::size_t i = 0;
  while (true) {
    out.push_back(path[i]);
    if (i + 1 >= path.size()) break;
    // The legal neighbour of path[i] that comes latest in the path.
    std::size_t next = i + 1;
    const int n = grid_.neighbours(path[i], nb);
    for (int k = 0; k < n; ++k) {
      const int p = position_[nb[k]];
      if (p > static_cast<int>(next)) next = static_cast<std::size_t>(p);
    }
    i = next;
  }
  for (int c : path) position_[c] = -1;
  path.swap(out);
}

bool AntPathProcessing::octilePath(int a, int b, bool diagonal_first, std::vector<int>& out) const {
  const std::size_t mark = out.size();
  const int dx = grid_.x(b) - grid_.x(a), dy = grid_.y(b) - grid_.y(a);
  const int sx = (dx > 0) - (dx < 0), sy = (dy > 0) - (dy < 0);
  const int diagonal = std::min(std::abs(dx), std::abs(dy));
  const int straight = std::max(std::abs(dx), std::abs(dy)) - diagonal;
  const bool along_x = std::abs(dx) > std::abs(dy);
  int at = a;
  auto step = [&](int mx, int my) {
    const int next = grid_.index(grid_.x(at) + mx, grid_.y(at) + my);
    if (!grid_.adjacent(at, next)) return false;
    out.push_back(next);
    at = next;
    return true;
  };
  for (int phase = 0; phase < 2; ++phase) {
    const bool diagonal_phase = (phase == 0) == diagonal_first;
    const int count = diagonal_phase ? diagonal : straight;
    for (int k = 0; k < count; ++k) {
      const bool ok = diagonal_phase ? step(sx, sy) : step(along_x ? sx : 0, along_x ? 0 : sy);
      if (!ok) {
        out.resize(mark);
        return false;
      }
    }
  }
  return true;
}

void AntPathProcessing::smoothWide(std::vector<int>& path, int range) {
  if (path.size() < 3 || range < 2) return;
  std::vector<double> walked(path.size(), 0.0);  // length of the path up to each node
  for (std::size_t i = 1; i < path.size(); ++i)
    walked[i] = walked[i - 1] + grid_.stepLength(path[i - 1], path[i]);
  std::vector<int> out{path.front()};
  std::size_t i = 0;
  while (i + 1 < path.size()) {
    std::size_t next = i + 1;
    const std::size_t last = std::min(path.size() - 1, i + static_cast<std::size_t>(range));
    for (std::size_t j = last; j > i + 1; --j) {
      const double dx = std::abs(grid_.x(path[j]) - grid_.x(path[i])),
                   dy = std::abs(grid_.y(path[j]) - grid_.y(path[i]));
      const double octile = std::max(dx, dy) + (AntGridView::kSqrt2 - 1.0) * std::min(dx, dy);
      if (octile >= walked[j] - walked[i] - 1e-9) continue;  // already as short as it gets
      if (octilePath(path[i], path[j], true, out) || octilePath(path[i], path[j], false, out)) {
        next = j;
        break;
      }
    }
    if (next == i + 1) out.push_back(path[i + 1]);
    i = next;
  }
  path.swap(out);
}

}  // namespace cosim
