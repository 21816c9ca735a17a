#pragma once
// SACO and SACOdm (Porta García, Montiel, Castillo, Sepúlveda, Melin, Applied Soft Computing 9
// (2009) 1102-1110) as implemented in seed 000 (Pěňčík 2014, §4.4-4.5): pheromone lives in the
// cells (a cell's value serves every edge into it); an ant at cell i moves to a free neighbour j
// with weight tau_j^alpha / xi_j^beta (eq. 4.5; xi_j = Euclidean distance from j to the goal);
// visited cells are held as temporary obstacles by a memory of capacity gamma; after every
// iteration tau <- (1 - rho) tau (eq. 4.3), then each ant deposits 1/L on its cells (Ant System,
// Dorigo 2004) and, for the elitist variant, the best-so-far path gets e / L_bs more.
// SACO is SACOdm with beta = 0 and gamma = 0. Path quality is the length (the seed replaced [12]'s
// fuzzy cost by it).
#include <cstdint>
#include <string>

#include "planning/grid/grid_planner.h"

namespace cosim {

struct SacoParams {
  std::string name = "sacodm";
  int ants = 3;         // seed: 3 in most experiments (2-6 studied)
  int iterations = 10;  // seed: 5-15
  double alpha = 2.0;   // pheromone exponent
  double beta = 1.0;    // distance exponent (0 = SACO)
  double rho = 0.2;     // evaporation rate, (0, 1]
  double tau0 = 0.5;    // initial pheromone (0.5 in all of the seed's experiments)
  int gamma = 1;        // memory capacity (0 = no memory)
  // "first": [12]'s memory, the first gamma visited cells are blocked until the walk has made
  // gamma steps; "rolling": the seed's §4.5.1 list of the last gamma visited cells.
  bool rolling_memory = true;
  double elitist_weight = 1.0;  // e of the Elitist Ant System; 0 = plain Ant System
  bool smoothing = true;        // light smoothing after the (always done) cycle removal
  int smoothing_range = 1;      // > 1: wider-range smoothing as MSAC's (not in the seed)
  bool conditional_diagonal = true;
  // Early stop (seed §2.6 inputs): a path no longer than this is good enough (0 = off) ...
  double sufficient_length = 0.0;
  // ... or no longer than this times the free-grid octile distance of start and goal (0 = off).
  double sufficient_ratio = 0.0;
  // A walk that has not reached the goal after this many steps x the number of cells gives up
  // (bounds the time of a pure random walk; the seed's walks had no bound).
  int max_walk_factor = 20;
};

class Saco : public GridPlanner {
 public:
  explicit Saco(SacoParams params = {}) : p_(std::move(params)) {}
  std::string name() const override { return p_.name; }
  // Counters include raw/loop-free/smoothed length of the very first walk (seed Fig. 6.5).
  GridPlanResult solveGrid(const GridQuery& query, const StopToken& stop) override;

 private:
  SacoParams p_;
};

}  // namespace cosim
