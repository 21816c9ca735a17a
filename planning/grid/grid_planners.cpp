#include "planning/grid/grid_planners.h"

#include <string>

#include "planning/grid/astar.h"
#include "planning/grid/basic_theta_star.h"
#include "planning/grid/bellman_ford.h"
#include "planning/grid/dijkstra.h"
#include "planning/grid/lazy_theta_star.h"
#include "planning/planner_registry.h"

namespace cosim {

GridMoves readGridMoves(ParamSet& params) {
  GridMoves moves;
  moves.connectivity =
      std::stoi(params.getString("connectivity", "0", {"0", "4", "8", "6", "18", "26"}));
  moves.corner_cutting = params.getBool("corner_cutting", false);
  return moves;
}

namespace {
// The factory of a planner whose only parameters are the moves.
template <class P>
GridPlannerFactory movesOnly() {
  return [](ParamSet& p) -> std::unique_ptr<GridPlanner> {
    return std::make_unique<P>(readGridMoves(p), p.file());
  };
}
}  // namespace

void registerGridPlanners(PlannerRegistry& r) {
  r.addGridPlanner("dijkstra", "grid", "Dijkstra's shortest path on the grid (optimal, uninformed)",
                   movesOnly<Dijkstra>());
  r.addGridPlanner("bellman_ford", "grid",
                   "Bellman-Ford (Moore's queue form) on the grid (optimal, labels every cell)",
                   movesOnly<BellmanFord>());
  r.addGridPlanner("astar", "grid", "A* with the octile/Manhattan heuristic (optimal for weight 1)",
                   [](ParamSet& p) -> std::unique_ptr<GridPlanner> {
                     AStar::Options o;
                     o.moves = readGridMoves(p);
                     o.heuristic_weight = p.getDouble("heuristic_weight", 1.0, 1.0, 100.0);
                     return std::make_unique<AStar>(o, p.file());
                   });
  r.addGridPlanner("theta_star", "grid",
                   "Basic Theta*: any-angle A* with supercover line of sight (Nash et al. 2007)",
                   movesOnly<BasicThetaStar>());
  r.addGridPlanner("lazy_theta_star", "grid",
                   "Lazy Theta*: Theta* checking line of sight on expansion (Nash et al. 2010)",
                   movesOnly<LazyThetaStar>());
}

}  // namespace cosim
