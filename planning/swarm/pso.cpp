#include "planning/swarm/pso.h"

#include <algorithm>
#include <limits>
#include <random>

#include "planning/grid/grid_distance.h"
#include "planning/swarm/layer_walk_search.h"

namespace cosim {

namespace {
// Largest particle state we allocate (floats: position, velocity and personal best of every
// particle); beyond it the query fails with a message instead of exhausting memory.
constexpr std::size_t kMaxStateFloats = std::size_t(1) << 27;  // 512 MiB
}  // namespace

GridPlanResult Pso::solveGrid(const GridQuery& query, const StopToken& stop) {
  LayerWalkSearch search(query, stop, p_.directions);
  if (!search.layer().error.empty()) return search.rejected();
  const OccupancyGrid& grid = search.grid();
  const std::size_t cells = grid.cellCount();
  const std::size_t P = static_cast<std::size_t>(p_.particles);
  if (3 * P * cells > kMaxStateFloats)
    return search.failure("grid too large for pso (" + std::to_string(cells) + " cells x " +
                          std::to_string(P) + " particles)",
                          PlannerStatus::InvalidProblem);
  const ExtendedNeighbourhood& moves = search.moves();
  std::mt19937_64 rng(query.seed);
  const Cell goal = search.layer().goal;

  std::vector<float> x(P * cells), v(P * cells, 0.0f), pbest(P * cells);
  std::vector<double> pbest_length(P, std::numeric_limits<double>::infinity());
  std::uniform_real_distribution<float> init(-1.0f, 1.0f);
  for (float& xi : x) xi = init(rng);

  // Decoding: the candidate with the highest priority minus goal_bias * octile distance.
  const float* priorities = nullptr;
  auto choose = [&](const Cell& c, int, const int* candidates, int n) {
    int best = 0;
    double best_score = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < n; ++i) {
      const NeighbourOffset& o = moves.offset(candidates[i]);
      const Cell t{c.x + o.dx, c.y + o.dy, 0};
      const double score =
          priorities[grid.index(t)] - p_.goal_bias * octileDistance(t.x - goal.x, t.y - goal.y, 0);
      if (score > best_score) best_score = score, best = i;
    }
    return best;
  };

  std::vector<Cell> path;
  std::vector<int> dirs;
  std::size_t gbest = 0;
  int iterations_done = 0;
  const float vmax = static_cast<float>(p_.v_max);
  for (int it = 0; it < p_.iterations; ++it) {
    for (std::size_t k = 0; k < P; ++k) {
      priorities = &x[k * cells];
      if (!search.walk(choose, path, dirs)) break;
      const double length = gridPathLength(path);
      if (length < pbest_length[k]) {
        pbest_length[k] = length;
        std::copy(x.begin() + k * cells, x.begin() + (k + 1) * cells, pbest.begin() + k * cells);
      }
      if (search.offer(path, length, it + 1)) gbest = k;
    }
    if (search.stopped() || search.best().empty()) break;
    ++iterations_done;
    if (it + 1 == p_.iterations) break;
    // Velocity and position update; r1, r2 per dimension from one 64-bit draw (two 32-bit
    // uniforms) to keep the generator cost at one call per dimension.
    const float* g = &pbest[gbest * cells];
    for (std::size_t k = 0; k < P; ++k) {
      float* xk = &x[k * cells];
      float* vk = &v[k * cells];
      const float* pk = &pbest[k * cells];
      for (std::size_t i = 0; i < cells; ++i) {
        const std::uint64_t bits = rng();
        const float r1 = static_cast<float>(bits & 0xffffffffu) * 2.3283064e-10f;
        const float r2 = static_cast<float>(bits >> 32) * 2.3283064e-10f;
        float vi = static_cast<float>(p_.inertia) * vk[i] +
                   static_cast<float>(p_.c1) * r1 * (pk[i] - xk[i]) +
                   static_cast<float>(p_.c2) * r2 * (g[i] - xk[i]);
        vi = std::clamp(vi, -vmax, vmax);
        vk[i] = vi;
        xk[i] += vi;
      }
    }
  }

  return search.result("time limit reached before any particle was decoded", iterations_done);
}

}  // namespace cosim
