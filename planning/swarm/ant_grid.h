#pragma once
// Seed 002, part A: the grid ant algorithm ("MA") of the lecture slides (summary section 2.2).
// Pheromone lives on cells (vertices). An ant at a cell picks one of its 3 (4 directions) or 7
// (8 directions) neighbours, or of the 16/24/32-cell extended neighbourhoods (section 2.3), with
//   p_i = tau_i^alpha * eta_i^beta / sum over the non-black-listed candidates,
// where eta_i = 1 / h_i and h_i grows with the "difference of angle (change of movement
// direction)". After all ants have walked, every cell evaporates and the best ant's cells are
// rewarded:  tau(t+1) = tau(t) - lambda * tau(t) + (Q / num on the best ant's cells).
#include <cstdint>

#include "planning/grid/grid_planner.h"

namespace cosim {

// The heuristic h_i of eta_i = 1 / h_i (the seed: "the difference of angle (change of movement
// direction)", no unit, nothing said about h_i = 0).
enum class AntHeading {
  // Ours: 1 + (deviation from the straight line to the goal, degrees)^2 + (turn, degrees).
  TurnAndGoal,
  // The seed as written, the turn only: 1 + turn / 45 degrees, i.e. 1 + the difference of the
  // seed's integer direction codes (0..7 for 8 directions), so a straight move has h = 1.
  Turn,
};

struct AntGridParams {
  // Defaults: the seed's parameter table (iterations 30~50, ants 20~30, initial pheromone 0.5,
  // evaporation 0.1, deposition 0.5, alpha 1, beta 0.5); 8 directions ("most often used").
  int ants = 20;
  int iterations = 30;
  double alpha = 1.0;
  double beta = 0.5;
  double evaporation = 0.1;  // lambda (the table's rho)
  double deposit = 0.5;      // Q
  double initial_pheromone = 0.5;
  int directions = 8;  // 4, 8, 16, 24 or 32
  AntHeading heading = AntHeading::TurnAndGoal;
  // The slides' step 3: "each time an ant moves from one vertex to the next, local evaporation
  // happens: the pheromone concentration is multiplied by a number < 1". They give no number;
  // this is 1 minus it, applied to every cell an ant enters (0 = off, our default). Ants walk
  // one after another, so the next ant sees the previous ants' marks, as with per-move updates.
  double local_evaporation = 0.0;
  // Not in the seed: shorten every ant's path with the staircase local search before the update.
  bool local_search = false;
};

class AntGrid : public GridPlanner {
 public:
  explicit AntGrid(AntGridParams params = {}) : p_(params) {}
  std::string name() const override { return "ant_grid"; }
  GridPlanResult solveGrid(const GridQuery& query, const StopToken& stop) override;

  // h_i = 1 + (deviation from the straight line to the goal)^2 + (turn from the previous move),
  // angles in degrees. Exposed for tests.
  static double headingCost(double previous_angle, bool has_previous, double move_angle,
                            double goal_angle);
  // The seed's h_i as written: 1 + turn / 45 degrees (1 for the first move).
  static double turnCost(double previous_angle, bool has_previous, double move_angle);

 private:
  AntGridParams p_;
};

}  // namespace cosim
