#pragma once
// Bellman-Ford on an occupancy grid (Bellman 1958, Ford 1956, Moore 1959; seed 003 Alg. 2): edge
// relaxation until no distance improves, in the queue-based form of Moore, which relaxes only the
// out-edges of cells whose distance changed (the same fixed point as |V| - 1 full passes, much
// sooner on grids). No heuristic and no early stop at the goal: it labels every reachable cell,
// which is why it is slow on large maps. All grid edge costs are positive, so the negative-cycle
// test of Alg. 2 could never fire and is left out.
#include <cstdint>
#include <string>
#include <vector>

#include "planning/grid/grid_node_table.h"
#include "planning/grid/grid_planner.h"
#include "planning/grid/grid_search_space.h"

namespace cosim {

class BellmanFord : public GridPlanner {
 public:
  explicit BellmanFord(const GridMoves& moves = {0, false}, std::string params_file = "")
      : moves_(moves), params_file_(std::move(params_file)) {}

  std::string name() const override { return "bellman_ford"; }
  GridPlanResult solveGrid(const GridQuery& query, const StopToken& stop) override;
  bool checksSegments() const override { return true; }

 private:
  GridMoves moves_;
  std::string params_file_;
  GridNodeTable<FixedCost> nodes_;
  std::vector<std::uint32_t> queue_;  // ring buffer; a cell is in it at most once
};

}  // namespace cosim
