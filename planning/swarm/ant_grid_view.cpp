#include "planning/swarm/ant_grid_view.h"

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

}  // namespace cosim
