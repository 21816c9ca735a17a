#include "planning/swarm/ant_common_000.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace cosim {

namespace {
// Compass order: E, NE, N, NW, W, SW, S, SE.
constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
constexpr int kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
}  // namespace

AntGridView::AntGridView(const OccupancyGrid& grid, int layer, bool conditional_diagonal)
    : nx_(grid.nx()),
      ny_(grid.ny()),
      layer_(layer),
      conditional_diagonal_(conditional_diagonal),
      blocked_(static_cast<std::size_t>(grid.nx()) * grid.ny()) {
  for (int y = 0; y < ny_; ++y)
    for (int x = 0; x < nx_; ++x) blocked_[index(x, y)] = grid.blocked(x, y, layer) ? 1 : 0;
}

int AntGridView::neighbours(int i, std::array<int, 8>& out) const {
  const int cx = x(i), cy = y(i);
  int n = 0;
  for (int d = 0; d < 8; ++d) {
    const int tx = cx + kDx[d], ty = cy + kDy[d];
    if (tx < 0 || ty < 0 || tx >= nx_ || ty >= ny_ || blocked_[index(tx, ty)]) continue;
    if (conditional_diagonal_ && kDx[d] != 0 && kDy[d] != 0 &&
        (blocked_[index(tx, cy)] || blocked_[index(cx, ty)]))
      continue;
    out[n++] = index(tx, ty);
  }
  return n;
}

bool AntGridView::adjacent(int a, int b) const {
  const int dx = x(b) - x(a), dy = y(b) - y(a);
  if (std::abs(dx) > 1 || std::abs(dy) > 1 || (dx == 0 && dy == 0) || blocked_[b]) return false;
  if (conditional_diagonal_ && dx != 0 && dy != 0)
    return !blocked_[index(x(b), y(a))] && !blocked_[index(x(a), y(b))];
  return true;
}

double AntGridView::distance(int a, int b) const {
  const double dx = x(a) - x(b), dy = y(a) - y(b);
  return std::sqrt(dx * dx + dy * dy);
}

double AntGridView::pathLength(const std::vector<int>& path) const {
  double total = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) total += stepLength(path[i - 1], path[i]);
  return total;
}

std::vector<Cell> AntGridView::toCells(const std::vector<int>& path) const {
  std::vector<Cell> cells;
  cells.reserve(path.size());
  for (int i : path) cells.push_back(cell(i));
  return cells;
}

std::optional<AntGridView> antGridForQuery(const GridQuery& query, bool conditional_diagonal,
                                           GridPlanResult& result) {
  const OccupancyGrid& g = *query.grid;
  if (query.start.z != query.goal.z) {
    // In metres, as the user gave them: grid layers are an internal detail.
    const double half = 0.5 * g.cellSize();
    const double start_z = g.cellCenter(query.start).z(), goal_z = g.cellCenter(query.goal).z();
    char heights[192];
    std::snprintf(heights, sizeof heights,
                  "2D planner: start and goal must be at the same height, in one layer of the "
                  "%.3g m grid (start in z %.3g-%.3g m, goal in z %.3g-%.3g m)",
                  g.cellSize(), start_z - half, start_z + half, goal_z - half, goal_z + half);
    result.message = heights;
    result.status = PlannerStatus::InvalidProblem;
    return std::nullopt;
  }
  if (g.blocked(query.start) || g.blocked(query.goal)) {
    result.message = g.blocked(query.start) ? "start cell is blocked" : "goal cell is blocked";
    result.status =
        g.blocked(query.start) ? PlannerStatus::InvalidStart : PlannerStatus::InvalidGoal;
    return std::nullopt;
  }
  if (query.start == query.goal) {
    result.success = true;
    result.status = PlannerStatus::ExactSolution;
    result.cells = {query.start};
    return std::nullopt;
  }
  return AntGridView(g, query.start.z, conditional_diagonal);
}

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
