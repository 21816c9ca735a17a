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

// The population and its operators over the walks of one query.
class Evolution {
 public:
  Evolution(const GeneticAlgorithmParams& p, LayerWalkSearch& search, std::uint64_t seed)
      : p_(p),
        search_(search),
        grid_(search.grid()),
        moves_(search.moves()),
        shortcut_(grid_, moves_),
        positions_(grid_),
        rng_(seed),
        goal_(search.layer().goal) {}

  const std::vector<Chromosome>& population() const { return population_; }

  // Initial population: walks guided by the ants' heuristic eta = 1 / h (no pheromone), or, in
  // the plain variant, walks that pick each legal move with equal probability. Stops early when
  // the search stops walking (time up, or the goal proved unreachable).
  void seedPopulation() {
    auto choose = [this](const Cell& c, int arrived, const int* candidates, int n) {
      return chooseInitialMove(c, arrived, candidates, n);
    };
    std::vector<int> dirs;
    for (int k = 0; k < p_.population; ++k) {
      Chromosome x;
      if (!search_.walk(choose, x.cells, dirs)) break;
      finish(x);
      population_.push_back(std::move(x));
    }
    if (!population_.empty()) pick_ = decltype(pick_)(0, population_.size() - 1);
  }

  std::size_t best() const {
    std::size_t b = 0;
    for (std::size_t i = 1; i < population_.size(); ++i)
      if (population_[i].length < population_[b].length) b = i;
    return b;
  }

  // One generation: the best survives (elitism), the rest are children of tournament winners,
  // crossed over with crossover_probability, mutated, their loops cut.
  void generation() {
    next_.clear();
    next_.push_back(population_[best()]);  // elitism
    while (next_.size() < population_.size()) {
      Chromosome c1, c2;
      const Chromosome& a = tournament();
      const Chromosome& b = tournament();
      if (unit_(rng_) < p_.crossover_probability) {
        crossover(a, b, c1, c2);
      } else {
        c1 = a;
        c2 = b;
      }
      for (Chromosome* c : {&c1, &c2}) {
        mutate(*c);
        finish(*c);
        if (next_.size() < population_.size()) next_.push_back(std::move(*c));
      }
    }
    population_.swap(next_);
  }

 private:
  int chooseInitialMove(const Cell& c, int arrived, const int* candidates, int n) {
    if (!p_.guided_initial) return std::uniform_int_distribution<int>(0, n - 1)(rng_);
    const double goal_angle = std::atan2(goal_.y - c.y, goal_.x - c.x);
    const double previous = arrived >= 0 ? moves_.offset(arrived).angle : 0.0;
    for (int i = 0; i < n; ++i)
      weights_[i] = 1.0 / AntGrid::headingCost(previous, arrived >= 0,
                                               moves_.offset(candidates[i]).angle, goal_angle);
    return rouletteIndex(weights_, n, rng_);
  }

  void finish(Chromosome& x) {
    removeLoops(x.cells, positions_);
    if (p_.local_search) shortcut_.improve(x.cells);
    x.length = gridPathLength(x.cells);
  }

  const Chromosome& tournament() {
    const Chromosome& a = population_[pick_(rng_)];
    const Chromosome& b = population_[pick_(rng_)];
    return a.length <= b.length ? a : b;
  }

  // One-point crossover at a random cell both parents pass through (not start or goal).
  bool crossover(const Chromosome& a, const Chromosome& b, Chromosome& c1, Chromosome& c2) {
    for (std::size_t j = 0; j < b.cells.size(); ++j) positions_.set(b.cells[j], j);
    std::vector<std::pair<std::size_t, std::size_t>> common;
    for (std::size_t i = 1; i + 1 < a.cells.size(); ++i) {
      const long j = positions_.find(b.cells, a.cells[i]);
      if (j > 0 && static_cast<std::size_t>(j) + 1 < b.cells.size()) common.push_back({i, j});
    }
    c1 = a;
    c2 = b;
    if (common.empty()) return false;
    const auto [i, j] =
        common[std::uniform_int_distribution<std::size_t>(0, common.size() - 1)(rng_)];
    c1.cells.assign(a.cells.begin(), a.cells.begin() + i + 1);
    c1.cells.insert(c1.cells.end(), b.cells.begin() + j + 1, b.cells.end());
    c2.cells.assign(b.cells.begin(), b.cells.begin() + j + 1);
    c2.cells.insert(c2.cells.end(), a.cells.begin() + i + 1, a.cells.end());
    return true;
  }

  // Each interior node mutates with mutation_probability.
  void mutate(Chromosome& x) {
    for (std::size_t i = 1; i + 1 < x.cells.size(); ++i) {
      if (unit_(rng_) >= p_.mutation_probability) continue;
      if (p_.shortening_mutation)
        x.cells[i] = shortestNeighbour(x.cells[i - 1], x.cells[i], x.cells[i + 1]);
      else
        moveToRandomNeighbour(x.cells[i - 1], x.cells[i], x.cells[i + 1]);
    }
  }

  // Tuncer-Yildirim mutation: the neighbour cell of `at` (or `at`) that shortens prev-at-next
  // most while keeping both moves legal.
  Cell shortestNeighbour(const Cell& prev, const Cell& at, const Cell& next) const {
    Cell best = at;
    double best_cost = dist(prev, best) + dist(best, next);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Cell q{at.x + dx, at.y + dy, 0};
        if ((dx == 0 && dy == 0) || q == prev || q == next || grid_.blocked(q)) continue;
        const double cost = dist(prev, q) + dist(q, next);
        if (cost < best_cost - 1e-12 && moves_.legalMove(grid_, prev, q) &&
            moves_.legalMove(grid_, q, next)) {
          best = q;
          best_cost = cost;
        }
      }
    return best;
  }

  // The plain variant's mutation: `at` moves to a random neighbour cell that keeps both moves
  // legal (it stays if there is none).
  void moveToRandomNeighbour(const Cell& prev, Cell& at, const Cell& next) {
    legal_.clear();
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Cell q{at.x + dx, at.y + dy, 0};
        if ((dx == 0 && dy == 0) || q == prev || q == next || grid_.blocked(q)) continue;
        if (moves_.legalMove(grid_, prev, q) && moves_.legalMove(grid_, q, next))
          legal_.push_back(q);
      }
    if (!legal_.empty())
      at = legal_[std::uniform_int_distribution<std::size_t>(0, legal_.size() - 1)(rng_)];
  }

  const GeneticAlgorithmParams& p_;
  LayerWalkSearch& search_;
  const OccupancyGrid& grid_;
  const ExtendedNeighbourhood& moves_;
  const PathShortcut shortcut_;
  CellPositions positions_;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
  std::uniform_int_distribution<std::size_t> pick_;  // a member of the population
  const Cell goal_;
  double weights_[32];
  std::vector<Chromosome> population_, next_;
  std::vector<Cell> legal_;
};

}  // namespace

GridPlanResult GeneticAlgorithm::solveGrid(const GridQuery& query, const StopToken& stop) {
  LayerWalkSearch search(query, stop, p_.directions);
  if (!search.layer().error.empty()) return search.rejected();
  Evolution evolution(p_, search, query.seed);
  evolution.seedPopulation();
  if (search.unreachable()) return search.result("", 0);  // "goal unreachable from start"
  if (evolution.population().empty())
    return search.failure("time limit reached before the first chromosome was built",
                          expiredStatus(search.deadline()));
  const Chromosome& first_best = evolution.population()[evolution.best()];
  search.offer(first_best.cells, first_best.length, 0);
  int generations_done = 0;
  for (int g = 0; g < p_.generations && !search.deadline().expired(); ++g) {
    evolution.generation();
    ++generations_done;
    const Chromosome& gb = evolution.population()[evolution.best()];
    search.offer(gb.cells, gb.length, g + 1);
  }
  return search.result("", generations_done);
}

}  // namespace cosim
