#include "planning/swarm/genetic_algorithm.h"

#include <cmath>
#include <random>

#include "planning/swarm/ant_grid.h"
#include "planning/swarm/grid_walk.h"
#include "planning/swarm/layer_walk_search.h"
#include "planning/swarm/path_shortcut.h"

namespace cosim {

namespace {

struct Chromosome {
  std::vector<Cell> cells;
  double length = 0.0;
};

// Remembers, for each cell, a position in one path; valid only while that path still holds the
// cell there, so it never needs clearing.
class CellPositions {
 public:
  explicit CellPositions(const OccupancyGrid& grid) : grid_(grid), pos_(grid.cellCount(), 0) {}
  void set(const Cell& c, std::size_t i) { pos_[grid_.index(c)] = i; }
  // Position of c in path, or -1.
  long find(const std::vector<Cell>& path, const Cell& c) const {
    const std::size_t i = pos_[grid_.index(c)];
    return i < path.size() && path[i] == c ? static_cast<long>(i) : -1;
  }

 private:
  const OccupancyGrid& grid_;
  std::vector<std::size_t> pos_;
};

// Cuts every loop: when a cell reappears, the cycle since its first visit is dropped.
void removeLoops(std::vector<Cell>& path, CellPositions& positions) {
  std::vector<Cell> out;
  out.reserve(path.size());
  for (const Cell& c : path) {
    const long seen = positions.find(out, c);
    if (seen >= 0) {
      out.resize(seen + 1);
      continue;
    }
    positions.set(c, out.size());
    out.push_back(c);
  }
  path.swap(out);
}

double dist(const Cell& a, const Cell& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

}  // namespace

GridPlanResult GeneticAlgorithm::solveGrid(const GridQuery& query) {
  LayerWalkSearch search(query, p_.directions);
  if (!search.layer().error.empty()) return search.rejected();
  const OccupancyGrid& grid = search.grid();
  const ExtendedNeighbourhood& moves = search.moves();
  const PathShortcut shortcut(grid, moves);
  CellPositions positions(grid);
  std::mt19937_64 rng(query.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Cell goal = search.layer().goal;

  // Initial population: walks guided by the ants' heuristic eta = 1 / h (no pheromone), or, in
  // the plain variant, walks that pick each legal move with equal probability.
  double weights[32];
  auto choose = [&](const Cell& c, int arrived, const int* candidates, int n) {
    if (!p_.guided_initial) return std::uniform_int_distribution<int>(0, n - 1)(rng);
    const double goal_angle = std::atan2(goal.y - c.y, goal.x - c.x);
    const double previous = arrived >= 0 ? moves.offset(arrived).angle : 0.0;
    for (int i = 0; i < n; ++i)
      weights[i] = 1.0 / AntGrid::headingCost(previous, arrived >= 0,
                                              moves.offset(candidates[i]).angle, goal_angle);
    return rouletteIndex(weights, n, rng);
  };
  auto finish = [&](Chromosome& x) {
    removeLoops(x.cells, positions);
    if (p_.local_search) shortcut.improve(x.cells);
    x.length = gridPathLength(x.cells);
  };
  std::vector<Chromosome> population;
  std::vector<int> dirs;
  for (int k = 0; k < p_.population; ++k) {
    Chromosome x;
    if (!search.walk(choose, x.cells, dirs)) break;
    finish(x);
    population.push_back(std::move(x));
  }
  if (search.unreachable()) return search.result("", 0);  // "goal unreachable from start"
  if (population.empty())
    return search.failure("time limit reached before the first chromosome was built",
                          expiredStatus(search.deadline()));

  auto bestOf = [](const std::vector<Chromosome>& pop) {
    std::size_t b = 0;
    for (std::size_t i = 1; i < pop.size(); ++i)
      if (pop[i].length < pop[b].length) b = i;
    return b;
  };
  std::uniform_int_distribution<std::size_t> pick(0, population.size() - 1);
  auto tournament = [&]() -> const Chromosome& {
    const Chromosome& a = population[pick(rng)];
    const Chromosome& b = population[pick(rng)];
    return a.length <= b.length ? a : b;
  };
  // One-point crossover at a random cell both parents pass through (not start or goal).
  auto crossover = [&](const Chromosome& a, const Chromosome& b, Chromosome& c1, Chromosome& c2) {
    for (std::size_t j = 0; j < b.cells.size(); ++j) positions.set(b.cells[j], j);
    std::vector<std::pair<std::size_t, std::size_t>> common;
    for (std::size_t i = 1; i + 1 < a.cells.size(); ++i) {
      const long j = positions.find(b.cells, a.cells[i]);
      if (j > 0 && static_cast<std::size_t>(j) + 1 < b.cells.size()) common.push_back({i, j});
    }
    c1 = a;
    c2 = b;
    if (common.empty()) return false;
    const auto [i, j] =
        common[std::uniform_int_distribution<std::size_t>(0, common.size() - 1)(rng)];
    c1.cells.assign(a.cells.begin(), a.cells.begin() + i + 1);
    c1.cells.insert(c1.cells.end(), b.cells.begin() + j + 1, b.cells.end());
    c2.cells.assign(b.cells.begin(), b.cells.begin() + j + 1);
    c2.cells.insert(c2.cells.end(), a.cells.begin() + i + 1, a.cells.end());
    return true;
  };
  // Tuncer-Yildirim mutation: node i moves to the neighbour cell that shortens the path most;
  // the plain variant moves it to a random neighbour cell that keeps both moves legal.
  std::vector<Cell> legal;
  auto mutate = [&](Chromosome& x) {
    for (std::size_t i = 1; i + 1 < x.cells.size(); ++i) {
      if (unit(rng) >= p_.mutation_probability) continue;
      const Cell prev = x.cells[i - 1], next = x.cells[i + 1];
      if (!p_.shortening_mutation) {
        legal.clear();
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const Cell q{x.cells[i].x + dx, x.cells[i].y + dy, 0};
            if ((dx == 0 && dy == 0) || q == prev || q == next || grid.blocked(q)) continue;
            if (moves.legalMove(grid, prev, q) && moves.legalMove(grid, q, next))
              legal.push_back(q);
          }
        if (!legal.empty())
          x.cells[i] = legal[std::uniform_int_distribution<std::size_t>(0, legal.size() - 1)(rng)];
        continue;
      }
      Cell best = x.cells[i];
      double best_cost = dist(prev, best) + dist(best, next);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const Cell q{x.cells[i].x + dx, x.cells[i].y + dy, 0};
          if ((dx == 0 && dy == 0) || q == prev || q == next || grid.blocked(q)) continue;
          const double cost = dist(prev, q) + dist(q, next);
          if (cost < best_cost - 1e-12 && moves.legalMove(grid, prev, q) &&
              moves.legalMove(grid, q, next)) {
            best = q;
            best_cost = cost;
          }
        }
      x.cells[i] = best;
    }
  };

  const std::size_t first_best = bestOf(population);
  search.offer(population[first_best].cells, population[first_best].length, 0);
  int generations_done = 0;
  std::vector<Chromosome> next;
  for (int g = 0; g < p_.generations && !search.deadline().expired(); ++g) {
    next.clear();
    next.push_back(population[bestOf(population)]);  // elitism
    while (next.size() < population.size()) {
      Chromosome c1, c2;
      const Chromosome& a = tournament();
      const Chromosome& b = tournament();
      if (unit(rng) < p_.crossover_probability) {
        crossover(a, b, c1, c2);
      } else {
        c1 = a;
        c2 = b;
      }
      for (Chromosome* c : {&c1, &c2}) {
        mutate(*c);
        finish(*c);
        if (next.size() < population.size()) next.push_back(std::move(*c));
      }
    }
    population.swap(next);
    ++generations_done;
    const Chromosome& gb = population[bestOf(population)];
    search.offer(gb.cells, gb.length, g + 1);
  }

  return search.result("", generations_done);
}

}  // namespace cosim
