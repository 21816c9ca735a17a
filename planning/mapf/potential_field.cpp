#include "planning/mapf/potential_field.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "planning/mapf/mapf_search_context.h"
#include "planning/mapf/step_arbiter.h"

namespace cosim {

namespace {

double distanceBetween(const Cell& a, const Cell& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

// Repulsion of the blocked cells at every free cell (the map's edge does not repel: on MovingAI
// maps it is the world's end, not a wall, and goals often lie on it).
std::vector<double> obstaclePotential(const OccupancyGrid& grid, double radius) {
  const int r = static_cast<int>(std::floor(radius));
  std::vector<double> u(static_cast<std::size_t>(grid.nx()) * grid.ny(), 0.0);
  for (int y = 0; y < grid.ny(); ++y)
    for (int x = 0; x < grid.nx(); ++x) {
      if (grid.blocked(x, y)) continue;
      double sum = 0.0;
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          const double d = std::hypot(dx, dy);
          if ((dx || dy) && d < radius && grid.inside(x + dx, y + dy) &&
              grid.blocked(x + dx, y + dy))
            sum += 1.0 / d - 1.0 / radius;
        }
      u[grid.index(x, y)] = sum;
    }
  return u;
}

}  // namespace

MapfResult PotentialField::solve(const MapfQuery& query, const StopToken& stop) {
  MapfSearchContext context(query, stop);
  const StopToken& deadline = context.deadline();
  const MapfGrid& grid = context.grid();
  const int n = context.agentCount();
  const int max_steps = options_.max_steps > 0 ? options_.max_steps : grid.cellCount();
  const std::vector<double> walls =
      obstaclePotential(context.instance().grid, options_.influence_radius);
  MapfResult result;

  std::vector<int> start(n), goal(n);
  for (int a = 0; a < n; ++a) {
    start[a] = context.start(a);
    goal[a] = context.goal(a);
  }
  const auto potential = [&](int agent, int cell, const std::vector<int>& positions) {
    const Cell c = grid.cell(cell);
    double u = options_.attraction * distanceBetween(c, grid.cell(goal[agent])) +
               options_.repulsion * walls[cell];
    for (int b = 0; b < n; ++b) {
      if (b == agent || positions[b] == cell) continue;
      const double d = distanceBetween(c, grid.cell(positions[b]));
      if (d < options_.influence_radius)
        u += options_.repulsion * (1.0 / d - 1.0 / options_.influence_radius);
    }
    return u;
  };

  StepArbiter arbiter(grid, start);
  for (int step = 0; !arbiter.finished(goal, max_steps, deadline, result); ++step) {
    const std::vector<int> now = arbiter.positions();
    arbiter.beginStep();
    for (int a = 0; a < n; ++a) {
      if (now[a] == goal[a]) continue;
      // Candidates by potential (ties: lower cell id); staying is one of them.
      std::vector<std::pair<double, int>> options{{potential(a, now[a], now), now[a]}};
      for (const int c : grid.neighbours(now[a])) options.push_back({potential(a, c, now), c});
      std::sort(options.begin(), options.end());
      for (const auto& [u, c] : options) {
        (void)u;
        if (c == now[a] || arbiter.tryMove(a, c)) break;  // downhill, or stay
      }
    }
    // The dynamics are deterministic in the positions: a step without motion repeats for ever.
    if (arbiter.commitStep() == 0) {
      result.message =
          "robots stuck in local minima of the potential at step " + std::to_string(step);
      result.status = searchStatus(false, deadline, PlannerStatus::ApproximateSolution);
      break;
    }
  }
  arbiter.storePaths(result);
  return context.finish(std::move(result));
}

}  // namespace cosim
