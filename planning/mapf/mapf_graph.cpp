#include "planning/mapf/mapf_graph.h"

#include <algorithm>

#include "planning/grid/grid_planner.h"
#include "core/input_error.h"

namespace cosim {

namespace {

// The bits of x, y and z interleaved (21 bits each).
std::uint64_t mortonKey(const Cell& c) {
  const auto spread = [](std::uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffull;
    v = (v | v << 16) & 0x1f0000ff0000ffull;
    v = (v | v << 8) & 0x100f00f00f00f00full;
    v = (v | v << 4) & 0x10c30c30c30c30c3ull;
    v = (v | v << 2) & 0x1249249249249249ull;
    return v;
  };
  return spread(static_cast<std::uint64_t>(c.x)) | spread(static_cast<std::uint64_t>(c.y)) << 1 |
         spread(static_cast<std::uint64_t>(c.z)) << 2;
}

}  // namespace

MapfGraph MapfGraph::fromGrid(const OccupancyGrid& grid, int connectivity) {
  const bool three_d = grid.is3D();
  const bool known = three_d ? (connectivity == 6 || connectivity == 18 || connectivity == 26)
                             : (connectivity == 4 || connectivity == 8);
  if (!known)
    throw InputError(
        "", "connectivity",
        three_d ? "a 3D grid is 6-, 18- or 26-connected, not " + std::to_string(connectivity)
                : "a 2D grid is 4- or 8-connected, not " + std::to_string(connectivity));
  MapfGraph g;
  g.connectivity_ = connectivity;
  g.nx_ = grid.nx(), g.ny_ = grid.ny(), g.nz_ = grid.nz();
  // Vertices numbered along a Z-order (Morton) curve rather than row by row: cells near each
  // other in any direction then get nearby numbers, so a breadth-first wave and PIBT's lookups
  // at a vertex's neighbours touch fewer cache lines of the adjacency and distance tables (the
  // searches' main cost on large maps). The numbering changes no result.
  std::vector<std::pair<std::uint64_t, std::size_t>> order;
  for (std::size_t i = 0; i < grid.cellCount(); ++i)
    if (!grid.data()[i]) order.emplace_back(mortonKey(grid.cellAt(i)), i);
  std::sort(order.begin(), order.end());
  g.vertex_of_index_.assign(grid.cellCount(), kNoVertex);
  for (const auto& [key, i] : order) {
    g.vertex_of_index_[i] = static_cast<int>(g.cells_.size());
    g.cells_.push_back(grid.cellAt(i));
  }

  // Moves in gridSteps' fixed order; each move's raw key is its midpoint in doubled
  // coordinates, made dense afterwards.
  const auto steps = gridSteps(GridMoves{connectivity, /*corner_cutting=*/false}, three_d);
  const std::uint64_t mx = 2 * static_cast<std::uint64_t>(g.nx_),
                      my = 2 * static_cast<std::uint64_t>(g.ny_);
  std::vector<std::uint64_t> raw;
  g.first_.reserve(g.cells_.size() + 1);
  for (const Cell& c : g.cells_) {
    g.first_.push_back(static_cast<int>(g.targets_.size()));
    for (const GridStep& s : steps) {
      if (!gridStepAllowed(grid, c, s, false)) continue;
      const Cell t{c.x + s.dx, c.y + s.dy, c.z + s.dz};
      g.targets_.push_back(g.vertex_of_index_[grid.index(t)]);
      raw.push_back((static_cast<std::uint64_t>(c.z + t.z) * my + (c.y + t.y)) * mx + (c.x + t.x));
    }
  }
  g.first_.push_back(static_cast<int>(g.targets_.size()));
  for (int v = 0; v < g.vertexCount(); ++v) g.max_degree_ = std::max(g.max_degree_, g.degree(v));

  std::vector<std::uint64_t> distinct = raw;
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  g.key_count_ = static_cast<std::uint32_t>(distinct.size());
  g.keys_.reserve(raw.size());
  for (const std::uint64_t k : raw)
    g.keys_.push_back(static_cast<std::uint32_t>(
        std::lower_bound(distinct.begin(), distinct.end(), k) - distinct.begin()));
  return g;
}

int MapfGraph::vertexOf(const Cell& c) const {
  if (c.x < 0 || c.y < 0 || c.z < 0 || c.x >= nx_ || c.y >= ny_ || c.z >= nz_) return kNoVertex;
  const std::size_t i = (static_cast<std::size_t>(c.z) * ny_ + c.y) * nx_ + c.x;
  return vertex_of_index_[i];
}

}  // namespace cosim
