#pragma once
// What seed 002's walk-based grid planners (ant_grid, mmas, pso, and ga for its first population)
// share around their agents' walks: the query's start layer (planar_layer.h) and move set, one
// GridWalk on it, what the end of a walk means for the whole search, and the shortest path walked
// so far. A walk that proves the goal unreachable ends the query with that message; one that runs
// out of time ends the walking; a path that reached the goal is offered as the new best. The
// planners differ only in how an agent picks its moves and what they learn from the paths.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/stop_token.h"
#include "planning/grid/grid_planner.h"
#include "planning/swarm/extended_neighbourhood.h"
#include "planning/swarm/grid_walk.h"
#include "planning/swarm/planar_layer.h"

namespace cosim {

class LayerWalkSearch {
 public:
  // The query's time limit starts now. A non-empty layer().error means the query cannot be
  // planned: return rejected().
  LayerWalkSearch(const GridQuery& query, const StopToken& stop, int directions);
  // The walker refers to this object's layer and moves.
  LayerWalkSearch(const LayerWalkSearch&) = delete;
  LayerWalkSearch& operator=(const LayerWalkSearch&) = delete;

  const StopToken& deadline() const { return deadline_; }
  const PlanarLayer& layer() const { return layer_; }
  const OccupancyGrid& grid() const { return layer_.grid; }
  const ExtendedNeighbourhood& moves() const { return moves_; }

  // One walk from the layer's start to its goal (GridWalk::walk; choose picks the moves): true if
  // path (and dirs, its moves) now holds one. False once the time is up or the goal has proved
  // unreachable: the search then walks no more, and result() says why.
  template <class Choose>
  bool walk(Choose&& choose, std::vector<Cell>& path, std::vector<int>& dirs) {
    last_ = walker_.walk(layer_.start, layer_.goal, choose, deadline_, path, dirs);
    return last_ == WalkOutcome::Reached;
  }
  bool stopped() const { return last_ != WalkOutcome::Reached; }
  bool unreachable() const { return last_ == WalkOutcome::Unreachable; }

  // Keeps path as the best if it is shorter than the best so far by more than 1e-12 (a tie keeps
  // the earlier path); iteration: the 1-based iteration that made it (0: before the first).
  // Returns whether it was kept.
  bool offer(const std::vector<Cell>& path, double length, int iteration);
  const std::vector<Cell>& best() const { return best_; }
  double bestLength() const { return best_length_; }
  int bestIteration() const { return best_iteration_; }

  // A failure with its reason and status, and the walk steps made so far.
  GridPlanResult failure(const std::string& message, PlannerStatus status) const;
  // The failure of a query whose layer cannot be planned (layer().error).
  GridPlanResult rejected() const { return failure(layer_.error, layer_.error_status); }
  // The ending: "goal unreachable from start" if a walk proved it; else the best path (lifted to
  // the query's grid) or, if there is none, the failure no_path, with the counters iterations,
  // best_iteration and expansions (walk steps).
  GridPlanResult result(const std::string& no_path, int iterations) const;

 private:
  const StopToken deadline_;
  const PlanarLayer layer_;
  const ExtendedNeighbourhood moves_;
  GridWalk walker_;
  WalkOutcome last_ = WalkOutcome::Reached;
  std::vector<Cell> best_;
  double best_length_ = std::numeric_limits<double>::infinity();
  int best_iteration_ = 0;
};

}  // namespace cosim
