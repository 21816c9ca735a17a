#pragma once
// MAX-MIN Ant System (T. Stuetzle, H. H. Hoos, "MAX-MIN Ant System", Future Generation Computer
// Systems 16 (2000) 889-914), the strongest of the three colonies in seed 002's Table I, on the
// grid. Pheromone lives on moves (cell, direction). Ants choose moves with the random
// proportional rule tau^alpha * eta^beta with eta = 1 / (detour_offset + detour), the detour
// being the move's length plus the octile distance left minus the octile distance before (0 for
// moves toward the goal; 1 / (length + distance to goal), the usual TSP-like choice, is nearly
// uniform far from the goal and made the ants' walks wander over whole 512 x 512 maps);
// the iteration-best ant's path is improved by local search (the paper's MMAS applies 2-opt/3-opt
// to every ant on the TSP; here the staircase shortcut of path_shortcut.h, on the best ant
// only, as it costs more than the walks); then all trails evaporate by rho, only the
// iteration-best ant (the best-so-far ant every 5th iteration) deposits 1 / L, and every trail
// is kept within [tau_min, tau_max] with tau_max = 1 / (rho L_best) and
// tau_min = tau_max (1 - p_best^(1/n)) / ((avg - 1) p_best^(1/n)) (paper, eq. 11).
#include "planning/grid/grid_planner.h"

namespace cosim {

// Measured (experiments/bench/ant_planners.cpp, 210 MovingAI queries, CPU time): the defaults
// reach a mean gap of 0.17% at 16x A*'s time; ants = 5, stall_iterations = 1 ("mmas_fast")
// 0.38% at 4.5x; without local search 12.5%.
struct MmasParams {
  int ants = 10;
  int iterations = 30;
  double alpha = 1.0;
  double beta = 2.0;
  double rho = 0.1;      // evaporation (the paper's TSP runs use 0.02 over thousands of iterations)
  double p_best = 0.05;  // probability of rebuilding the best path at convergence (sets tau_min)
  // Not in the paper: stop after this many iterations without a shorter path (0: never).
  int stall_iterations = 5;
  double detour_offset = 0.1;  // eta of a move without detour is 1 / detour_offset
  int directions = 8;          // 4, 8, 16, 24 or 32 (seed 002's neighbourhoods)
  bool local_search = true;
};

class Mmas : public GridPlanner {
 public:
  explicit Mmas(MmasParams params = {}) : p_(params) {}
  std::string name() const override { return "mmas"; }
  GridPlanResult solveGrid(const GridQuery& query, const StopToken& stop) override;

 private:
  MmasParams p_;
};

}  // namespace cosim
