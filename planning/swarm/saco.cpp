#include "planning/swarm/saco.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/stop_token.h"
#include "planning/swarm/ant_path_processing.h"

namespace cosim {

namespace {

constexpr long long kNever = std::numeric_limits<long long>::min() / 2;

// True if goal can be reached from start at all: random walks would otherwise spend their whole
// budget before reporting "no path". A flood fill costs one pass over the grid.
bool reachable(const AntGridView& grid, int start, int goal) {
  std::vector<unsigned char> seen(grid.cellCount(), 0);
  std::vector<int> stack{start};
  seen[start] = 1;
  std::array<int, 8> nb;
  while (!stack.empty()) {
    const int c = stack.back();
    stack.pop_back();
    if (c == goal) return true;
    const int n = grid.neighbours(c, nb);
    for (int k = 0; k < n; ++k)
      if (!seen[nb[k]]) {
        seen[nb[k]] = 1;
        stack.push_back(nb[k]);
      }
  }
  return false;
}

class SacoColony {
 public:
  SacoColony(const SacoParams& p, const AntGridView& grid, int start, int goal, std::uint64_t seed)
      : p_(p),
        grid_(grid),
        start_(start),
        goal_(goal),
        rng_(seed),
        tau_(grid.cellCount(), p.tau0),
        position_(grid.cellCount(), -1),
        stamp_(grid.cellCount(), kNever),
        processing_(grid) {}

  // One ant's walk from start to goal (seed §2.6 step 3 with memory, §4.5.1-4.5.2); returns the
  // processed path, empty if the walk gave up. raw_length: length before any processing.
  std::vector<int> walk(const StopToken& deadline, double& raw_length) {
    clock_ += p_.gamma + 2;  // older walks' visits never count as recent
    const long long walk_start = clock_;
    std::vector<int> path{start_};
    position_[start_] = 0;
    stamp_[start_] = clock_;
    raw_length = 0.0;
    const long long max_steps = static_cast<long long>(p_.max_walk_factor) * grid_.cellCount();
    std::array<int, 8> nb;
    double weight[8];
    long long s = 0;
    for (; path.back() != goal_ && s < max_steps; ++s) {
      if ((s & 4095) == 4095 && deadline.expired()) break;
      const int at = path.back();
      const int n = grid_.neighbours(at, nb);
      if (n == 0) break;
      int allowed[8], na = 0;
      for (int k = 0; k < n; ++k)
        if (!heldByMemory(nb[k], s, walk_start)) allowed[na++] = nb[k];
      if (na == 0) {
        // §4.5.1: memory leaves no way out, so the temporary obstacles around are lifted.
        for (int k = 0; k < n; ++k) {
          stamp_[nb[k]] = kNever;
          allowed[na++] = nb[k];
        }
      }
      const int next = choose(allowed, na, weight);
      ++clock_;
      raw_length += grid_.stepLength(at, next);
      stamp_[next] = clock_;
      // Immediate cycle removal (§4.5.2): returning to a cell on the path cuts the loop.
      if (position_[next] >= 0) {
        const std::size_t keep = static_cast<std::size_t>(position_[next]) + 1;
        for (std::size_t j = keep; j < path.size(); ++j) position_[path[j]] = -1;
        path.resize(keep);
      } else {
        position_[next] = static_cast<int>(path.size());
        path.push_back(next);
      }
    }
    steps_ += s;
    for (int c : path) position_[c] = -1;
    if (path.back() != goal_) return {};
    loop_free_length_ = grid_.pathLength(path);
    if (p_.smoothing) processing_.smoothLightly(path);
    if (p_.smoothing_range > 1) {
      processing_.smoothWide(path, p_.smoothing_range);
      processing_.removeCycles(path);  // a shortcut may cross a later part of the path
    }
    return path;
  }

  void evaporate() {
    for (double& t : tau_) t *= 1.0 - p_.rho;
  }
  void deposit(const std::vector<int>& path, double amount) {
    for (int c : path) tau_[c] += amount;
  }
  long long steps() const { return steps_; }
  double loopFreeLength() const { return loop_free_length_; }

 private:
  // The seed's memory gamma: a temporary obstacle on a recently visited cell.
  bool heldByMemory(int c, long long steps_done, long long walk_start) const {
    if (p_.gamma <= 0) return false;
    if (p_.rolling_memory) return stamp_[c] >= clock_ - p_.gamma;  // the last gamma cells
    // [12]: the cells visited so far stay blocked until the walk has made gamma steps.
    return steps_done < p_.gamma && stamp_[c] >= walk_start;
  }

  // Roulette over tau_j^alpha / xi_j^beta (eq. 4.5, normalised over the neighbours).
  int choose(const int* cells, int n, double* weight) {
    if (p_.beta > 0.0)
      for (int k = 0; k < n; ++k)
        if (cells[k] == goal_) return goal_;  // xi = 0: infinite weight
    double total = 0.0;
    for (int k = 0; k < n; ++k) {
      double w = std::pow(tau_[cells[k]], p_.alpha);
      if (p_.beta > 0.0) w /= std::pow(grid_.distance(cells[k], goal_), p_.beta);
      weight[k] = w;
      total += w;
    }
    double r = std::uniform_real_distribution<double>(0.0, total)(rng_);
    for (int k = 0; k < n; ++k) {
      r -= weight[k];
      if (r < 0.0) return cells[k];
    }
    return cells[n - 1];
  }

  const SacoParams& p_;
  const AntGridView& grid_;
  const int start_, goal_;
  std::mt19937_64 rng_;
  std::vector<double> tau_;
  std::vector<int> position_;     // index of a cell in the current (loop-free) walk, or -1
  std::vector<long long> stamp_;  // clock at the cell's last visit
  AntPathProcessing processing_;
  long long clock_ = 0, steps_ = 0;
  double loop_free_length_ = 0.0;
};

}  // namespace

GridPlanResult Saco::solveGrid(const GridQuery& query, const StopToken& stop) {
  const StopToken deadline(query.time_limit_s, stop);
  GridPlanResult result;
  const std::optional<AntGridView> ant_grid =
      antGridForQuery(query, p_.conditional_diagonal, result);
  if (!ant_grid) return result;  // rejected, or start == goal
  const AntGridView& grid = *ant_grid;
  const int start = grid.index(query.start), goal = grid.index(query.goal);
  if (!reachable(grid, start, goal)) {
    result.message = "goal is not reachable from the start";
    result.status = PlannerStatus::NoSolution;
    result.time_ms = deadline.elapsedMs();
    return result;
  }
  const double dx = std::abs(grid.x(start) - grid.x(goal)),
               dy = std::abs(grid.y(start) - grid.y(goal));
  const double octile = std::max(dx, dy) + (AntGridView::kSqrt2 - 1.0) * std::min(dx, dy);
  double good_enough = p_.sufficient_length;
  if (p_.sufficient_ratio > 0.0) good_enough = std::max(good_enough, p_.sufficient_ratio * octile);

  SacoColony colony(p_, grid, start, goal, query.seed);
  std::vector<int> best;
  double best_length = std::numeric_limits<double>::infinity();
  int iterations = 0, walks = 0, failed = 0;
  for (int it = 0; it < p_.iterations && !deadline.expired(); ++it) {
    std::vector<std::vector<int>> paths;
    std::vector<double> lengths;
    bool all_same = true;
    for (int k = 0; k < p_.ants && !deadline.expired(); ++k) {
      double raw = 0.0;
      std::vector<int> path = colony.walk(deadline, raw);
      ++walks;
      if (walks == 1) {
        result.counters["first_walk_raw_length"] = raw;
        result.counters["first_walk_loop_free_length"] =
            path.empty() ? 0.0 : colony.loopFreeLength();
        result.counters["first_walk_smoothed_length"] = grid.pathLength(path);
      }
      if (path.empty()) {
        ++failed;
        all_same = false;
        continue;
      }
      if (!paths.empty() && path != paths.front()) all_same = false;
      lengths.push_back(grid.pathLength(path));
      if (lengths.back() < best_length) {
        best_length = lengths.back();
        best = path;
      }
      paths.push_back(std::move(path));
    }
    ++iterations;
    colony.evaporate();  // eq. 4.3
    for (std::size_t k = 0; k < paths.size(); ++k) colony.deposit(paths[k], 1.0 / lengths[k]);
    if (p_.elitist_weight > 0.0 && !best.empty())
      colony.deposit(best, p_.elitist_weight / best_length);  // EAS daemon action
    if (good_enough > 0.0 && best_length <= good_enough + 1e-9) break;
    if (p_.ants > 1 && all_same && static_cast<int>(paths.size()) == p_.ants) break;
  }
  result.counters["iterations"] = iterations;
  result.counters["walks"] = walks;
  result.counters["failed_walks"] = failed;
  result.counters["expansions"] = static_cast<double>(colony.steps());
  result.success = !best.empty();
  result.status = searchStatus(result.success, deadline, PlannerStatus::LimitReached);
  if (result.success) {
    result.cells = grid.toCells(best);
    result.length = best_length;
  } else {
    result.message = deadline.expired() ? "time limit reached before any ant reached the goal"
                                        : "no ant reached the goal within its walk limit";
  }
  result.time_ms = deadline.elapsedMs();
  return result;
}

}  // namespace cosim
