#include "planning/mapf/mapf_memory_estimate.h"

#include <algorithm>
#include <cstdint>
#include <set>
#include <tuple>
#include <vector>

#include "core/input_error.h"

namespace cosim {

namespace {

std::string megabytes(double bytes) {
  return std::to_string(static_cast<long>(bytes / (1 << 20)));
}

struct FreeCells {
  long count = 0;
  bool distances_fit_16_bits = true;
};

// The free cells and whether GoalDistanceTable will store 16-bit entries, judged on the grid
// without building the planners' graph: fewer than 65535 free cells, or twice the
// eccentricity of one cell per connected part under axis moves (6/4-neighbourhood) below that.
// Distances with diagonal moves are never longer, so the bound holds for every connectivity.
FreeCells freeCells(const OccupancyGrid& grid) {
  FreeCells f;
  const std::size_t n = static_cast<std::size_t>(grid.nx()) * grid.ny() * grid.nz();
  const std::uint8_t* blocked = grid.data();
  for (std::size_t i = 0; i < n; ++i) f.count += blocked[i] ? 0 : 1;
  if (f.count < 0xffff) return f;
  std::vector<int> depth(n, -1);
  std::vector<std::size_t> queue;
  int eccentricity = 0;
  for (std::size_t root = 0; root < n; ++root) {
    if (blocked[root] || depth[root] >= 0) continue;
    depth[root] = 0;
    queue.assign(1, root);
    for (std::size_t k = 0; k < queue.size(); ++k) {
      const Cell c = grid.cellAt(queue[k]);
      const int d = depth[queue[k]];
      eccentricity = std::max(eccentricity, d);
      const Cell steps[6] = {{c.x - 1, c.y, c.z}, {c.x + 1, c.y, c.z}, {c.x, c.y - 1, c.z},
                             {c.x, c.y + 1, c.z}, {c.x, c.y, c.z - 1}, {c.x, c.y, c.z + 1}};
      for (const Cell& w : steps) {
        if (grid.blocked(w)) continue;
        const std::size_t j = grid.index(w);
        if (depth[j] < 0) depth[j] = d + 1, queue.push_back(j);
      }
    }
  }
  f.distances_fit_16_bits = 2 * eccentricity + 1 < 0xffff;
  return f;
}

MapfMemoryEstimate lazyGoalTables(const MapfInstance& instance) {
  std::set<std::tuple<int, int, int>> goals;
  for (const Cell& g : instance.goals) goals.insert({g.x, g.y, g.z});
  const FreeCells free = freeCells(instance.grid);
  const int entry = free.distances_fit_16_bits ? 2 : 4;
  MapfMemoryEstimate e;
  e.bytes = static_cast<double>(goals.size()) * static_cast<double>(free.count) * entry;
  e.breakdown = std::to_string(goals.size()) + " goals x " + std::to_string(free.count) +
                " free cells x " + std::to_string(entry) + " bytes";
  return e;
}

}  // namespace

MapfMemoryEstimate estimateMapfTableMemory(const MapfInstance& instance,
                                           const std::string& planner) {
  if (planner == "lacam" || planner == "pibt") return lazyGoalTables(instance);
  const double cells =
      static_cast<double>(instance.grid.nx()) * instance.grid.ny() * instance.grid.nz();
  MapfMemoryEstimate e;
  if (planner == "hca_star" || planner == "whca_star" || planner == "cbs") {
    // Reverse Resumable A*: std::vector<int> g and std::vector<uint8_t> closed per agent.
    e.bytes = instance.agentCount() * cells * 5.0;
    e.breakdown = std::to_string(instance.agentCount()) + " agents x " +
                  std::to_string(static_cast<long>(cells)) + " cells x 5 bytes";
  } else {
    // Shared per-cell tables: the largest are a space-time search's g, parent and noise (16
    // bytes a cell) and the reservation table (8).
    e.bytes = cells * 24.0;
    e.breakdown = std::to_string(static_cast<long>(cells)) + " cells x 24 bytes";
  }
  return e;
}

void checkMapfTableMemory(const MapfInstance& instance, const std::string& planner,
                          const std::string& file) {
  const MapfMemoryEstimate e = estimateMapfTableMemory(instance, planner);
  if (e.bytes <= static_cast<double>(kMaxMapfTableBytes)) return;
  throw InputError(file, "agents",
                   planner + "'s tables would need " + megabytes(e.bytes) + " MB (" + e.breakdown +
                       "), more than the " + megabytes(kMaxMapfTableBytes) +
                       " MB allowed (fewer agents, a smaller map, or lacam or pibt, whose "
                       "distance tables cover free cells only)");
}

}  // namespace cosim
