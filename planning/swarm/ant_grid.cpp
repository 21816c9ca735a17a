#include "planning/swarm/ant_grid.h"

#include <cmath>
#include <random>

#include "planning/swarm/grid_walk.h"
#include "planning/swarm/layer_walk_search.h"
#include "planning/swarm/path_shortcut.h"

namespace cosim {

namespace {
double angleBetween(double a, double b) {
  const double d = std::fabs(std::remainder(a - b, 2.0 * M_PI));
  return d;
}
}  // namespace

double AntGrid::headingCost(double previous_angle, bool has_previous, double move_angle,
                            double goal_angle) {
  // The seed names h_i "the difference of angle (change of movement direction)" but gives
  // neither its unit nor what happens at h_i = 0. We count degrees and add 1 (a straight move
  // has h = 1, not 0). A change of heading alone says nothing about where the goal is: ants
  // guided only by it (or by a linear goal term) wander, and with the seed's weak beta = 0.5 their
  // best paths on a 100 x 100 map were 2-3 times the optimum. So h also holds the square of the
  // move's deviation from the straight line to the goal (our reading of "difference of angle";
  // the seed's start and goal are opposite corners): a move 45 degrees off the goal direction
  // weighs (1/2026)^0.5 = 0.022 against one toward it, so walks head for the goal and the
  // pheromone decides around obstacles. Measured alternatives: experiments/reproduce/
  // seed002_ant_vs_ga.cpp's header.
  const double degree = M_PI / 180.0;
  const double off_goal = angleBetween(move_angle, goal_angle) / degree;
  double h = 1.0 + off_goal * off_goal;
  if (has_previous) h += angleBetween(move_angle, previous_angle) / degree;
  return h;
}

double AntGrid::turnCost(double previous_angle, bool has_previous, double move_angle) {
  if (!has_previous) return 1.0;
  return 1.0 + angleBetween(move_angle, previous_angle) / (M_PI / 4.0);
}

GridPlanResult AntGrid::solveGrid(const GridQuery& query, const StopToken& stop) {
  LayerWalkSearch search(query, stop, p_.directions);
  if (!search.layer().error.empty()) return search.rejected();
  const OccupancyGrid& grid = search.grid();
  const ExtendedNeighbourhood& moves = search.moves();
  const PathShortcut shortcut(grid, moves);
  std::mt19937_64 rng(query.seed);
  std::vector<double> tau(grid.cellCount(), p_.initial_pheromone);

  std::vector<Cell> path;
  std::vector<int> dirs;
  std::vector<std::vector<Cell>> iteration_paths(p_.ants);
  double weights[32];
  const Cell goal = search.layer().goal;
  auto choose = [&](const Cell& c, int arrived, const int* candidates, int n) {
    const double goal_angle = std::atan2(goal.y - c.y, goal.x - c.x);
    const double previous = arrived >= 0 ? moves.offset(arrived).angle : 0.0;
    for (int i = 0; i < n; ++i) {
      const NeighbourOffset& o = moves.offset(candidates[i]);
      const double t = tau[grid.index(c.x + o.dx, c.y + o.dy)];
      const double h = p_.heading == AntHeading::Turn
                           ? turnCost(previous, arrived >= 0, o.angle)
                           : headingCost(previous, arrived >= 0, o.angle, goal_angle);
      const double eta = 1.0 / h;
      weights[i] = powExponent(t, p_.alpha) * powExponent(eta, p_.beta);
    }
    return rouletteIndex(weights, n, rng);
  };

  int iterations_done = 0;
  for (int it = 0; it < p_.iterations && !search.stopped(); ++it) {
    int ants_done = 0;
    for (int k = 0; k < p_.ants; ++k) {
      if (!search.walk(choose, path, dirs)) break;
      if (p_.local_evaporation > 0.0)
        for (std::size_t i = 1; i < path.size(); ++i)
          tau[grid.index(path[i])] *= 1.0 - p_.local_evaporation;
      if (p_.local_search) shortcut.improve(path);
      search.offer(path, gridPathLength(path), it + 1);
      iteration_paths[ants_done++] = path;
    }
    if (ants_done == 0) break;
    ++iterations_done;
    // tau(t+1) = tau(t) - lambda tau(t) + Q/num on the nodes of the best ant. "The best ant" is
    // the elite (best-so-far) ant, as the seed's "elite" wording suggests.
    for (double& t : tau) t -= p_.evaporation * t;
    for (const Cell& c : search.best()) tau[grid.index(c)] += p_.deposit / p_.ants;
    // Stop when every ant built the same path (the seed's convergence criterion).
    bool converged = ants_done == p_.ants;
    for (int k = 1; k < ants_done && converged; ++k)
      converged = iteration_paths[k] == iteration_paths[0];
    if (converged) break;
  }

  return search.result("time limit reached before any ant arrived", iterations_done);
}

}  // namespace cosim
