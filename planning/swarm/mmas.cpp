#include "planning/swarm/mmas.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "planning/grid/grid_distance.h"
#include "planning/swarm/grid_walk.h"
#include "planning/swarm/layer_walk_search.h"
#include "planning/swarm/path_shortcut.h"

namespace cosim {

namespace {
// Trails on every (cell, direction) of a large map would cost a full sweep per iteration to
// evaporate; instead each trail remembers when it was last written and is decayed when read.
// Reading gives max(tau_min, min(tau_max, tau * (1 - rho)^age)), which equals evaporating and
// clamping every iteration while the bounds stay fixed (they change only when L_best improves).
class LazyTrails {
 public:
  LazyTrails(std::size_t size, int iterations, double rho, double initial)
      : value_(size, static_cast<float>(initial)), written_(size, 0), decay_(iterations + 2) {
    for (std::size_t a = 0; a < decay_.size(); ++a) decay_[a] = std::pow(1.0 - rho, a);
  }
  void setBounds(double lo, double hi) { lo_ = lo, hi_ = hi; }
  // The bounds of the paper's eq. 11 for the best path so far (best_cells cells, best_length
  // long) with D moves per cell: tau_max = 1 / (rho L_best),
  // tau_min = tau_max (1 - p_best^(1/n)) / ((avg - 1) p_best^(1/n)).
  void setBounds(const MmasParams& p, std::size_t best_cells, double best_length, int D) {
    const double tau_max = 1.0 / (p.rho * best_length);
    const double root = std::pow(p.p_best, 1.0 / std::max<std::size_t>(1, best_cells - 1));
    const double avg = std::max(2.0, D / 2.0);
    const double tau_min = std::min(tau_max, tau_max * (1.0 - root) / ((avg - 1.0) * root));
    setBounds(tau_min, tau_max);
  }
  double read(std::size_t i, int now) const {
    const double v = value_[i] * decay_[now - written_[i]];
    return std::clamp(v, lo_, hi_);
  }
  void add(std::size_t i, int now, double amount) {
    value_[i] = static_cast<float>(std::min(hi_, read(i, now) + amount));
    written_[i] = static_cast<std::uint16_t>(now);
  }
  // Deposits 1 / length on the moves of the path (after local search the moves are recomputed
  // from the cells).
  void deposit(const std::vector<Cell>& path, double length, const OccupancyGrid& grid,
               const ExtendedNeighbourhood& moves, int now) {
    const double amount = 1.0 / length;
    const std::size_t D = moves.directions();
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      const Cell& a = path[i];
      const Cell& b = path[i + 1];
      const int k = moves.indexOf(b.x - a.x, b.y - a.y);
      add(grid.index(a) * D + k, now, amount);
    }
  }

 private:
  std::vector<float> value_;
  std::vector<std::uint16_t> written_;
  std::vector<double> decay_;
  double lo_ = 0.0, hi_ = std::numeric_limits<double>::infinity();
};

// No path with D moves per cell can be shorter than this free-space bound.
double freeSpaceLowerBound(const Cell& start, const Cell& goal, int D) {
  const double dx = std::abs(start.x - goal.x), dy = std::abs(start.y - goal.y);
  return D == 4   ? dx + dy
         : D == 8 ? octileDistance(static_cast<int>(dx), static_cast<int>(dy), 0)
                  : std::hypot(dx, dy);
}
}  // namespace

GridPlanResult Mmas::solveGrid(const GridQuery& query, const StopToken& stop) {
  LayerWalkSearch search(query, stop, p_.directions);
  if (!search.layer().error.empty()) return search.rejected();
  const OccupancyGrid& grid = search.grid();
  const ExtendedNeighbourhood& moves = search.moves();
  const int D = moves.directions();
  const PathShortcut shortcut(grid, moves);
  std::mt19937_64 rng(query.seed);
  const Cell start = search.layer().start, goal = search.layer().goal;
  // Until the first path exists, tau_max is estimated from the straight-line (octile) length.
  const double first_estimate =
      std::max(1.0, octileDistance(start.x - goal.x, start.y - goal.y, 0));
  LazyTrails tau(grid.cellCount() * D, p_.iterations, p_.rho, 1.0 / (p_.rho * first_estimate));

  int now = 0;
  double weights[32];
  auto choose = [&](const Cell& c, int, const int* candidates, int n) {
    const std::size_t base = grid.index(c) * D;
    const double h_here = octileDistance(c.x - goal.x, c.y - goal.y, 0);
    for (int i = 0; i < n; ++i) {
      const NeighbourOffset& o = moves.offset(candidates[i]);
      // Detour of the move over the straight-line estimate: 0 for every move that keeps an
      // optimal free-space route open, up to 2x its length for a move away from the goal.
      const double detour =
          o.length + octileDistance(c.x + o.dx - goal.x, c.y + o.dy - goal.y, 0) - h_here;
      const double eta = 1.0 / (p_.detour_offset + std::max(0.0, detour));
      weights[i] =
          powExponent(tau.read(base + candidates[i], now), p_.alpha) * powExponent(eta, p_.beta);
    }
    return rouletteIndex(weights, n, rng);
  };

  // No path can be shorter than this free-space bound; reaching it ends the search early.
  const double lower_bound = freeSpaceLowerBound(start, goal, D);
  std::vector<Cell> path, iteration_best_path;
  std::vector<int> dirs;
  const std::vector<Cell>& best = search.best();
  int iterations_done = 0, improvements = 0;
  for (int it = 0; it < p_.iterations && !search.stopped(); ++it) {
    double iteration_best = std::numeric_limits<double>::infinity();
    iteration_best_path.clear();
    for (int k = 0; k < p_.ants; ++k) {
      if (!search.walk(choose, path, dirs)) break;
      const double length = gridPathLength(path);
      if (length < iteration_best) {
        iteration_best = length;
        iteration_best_path = path;
      }
      search.offer(path, length, it + 1);
    }
    if (iteration_best_path.empty()) break;
    if (p_.local_search) {
      // Local search on the iteration-best ant only (Stuetzle and Hoos apply it to every ant;
      // here it costs more than the walks, and only the iteration-best ant deposits).
      improvements += shortcut.improve(iteration_best_path);
      iteration_best = gridPathLength(iteration_best_path);
      search.offer(iteration_best_path, iteration_best, it + 1);
    }
    ++iterations_done;
    const double best_length = search.bestLength();
    if (best_length <= lower_bound + 1e-9) break;  // provably optimal
    if (p_.stall_iterations > 0 && iterations_done - search.bestIteration() >= p_.stall_iterations)
      break;
    ++now;  // one evaporation step for every trail (applied lazily)
    tau.setBounds(p_, best.size(), best_length, D);
    // Only the iteration-best ant deposits, the best-so-far ant every 5th iteration.
    if ((it % 5) == 4)
      tau.deposit(best, best_length, grid, moves, now);
    else
      tau.deposit(iteration_best_path, iteration_best, grid, moves, now);
  }

  GridPlanResult result =
      search.result("time limit reached before any ant arrived", iterations_done);
  // An unreachable goal is reported with the walk steps alone, like the other grid planners.
  if (!search.unreachable()) result.counters["local_search_moves"] = improvements;
  return result;
}

}  // namespace cosim
