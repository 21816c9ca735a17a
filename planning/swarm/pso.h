#pragma once
// Particle swarm optimisation for the shortest path with priority-based encoding, after
// A. W. Mohemmed, N. C. Sahoo, T. K. Geok, "Solving shortest path problem using particle swarm
// optimization", Applied Soft Computing 8 (2008) 1643-1653 (cited by seed 000). A particle is a
// vector of priorities, one per cell; it is decoded into a path by walking from the start to
// the free, unvisited neighbour of highest priority, stepping back out of dead ends. Particles
// move with the inertia-weight update v = w v + c1 r1 (pbest - x) + c2 r2 (gbest - x),
// x = x + v (r1, r2 uniform per dimension; velocities clamped to +-v_max).
//
// Deviation: the paper decodes on graphs of a few hundred nodes with random priorities; on a
// grid of 10^5 cells random priorities decode to a random depth-first walk. So the decoder ranks
// a neighbour by its priority minus goal_bias times its octile distance to the goal (the
// priorities then learn where to leave the straight line), and the paper's noising local search
// is not used.
#include "planning/grid/grid_planner.h"

namespace cosim {

struct PsoParams {
  int particles = 20;
  int iterations = 50;
  double inertia = 0.729;  // w (Clerc's constriction values, as common PSO practice)
  double c1 = 1.49445;     // cognitive
  double c2 = 1.49445;     // social
  double v_max = 1.0;
  double goal_bias = 1.0;  // priority units per cell of octile distance to the goal
  int directions = 8;      // 4, 8, 16, 24 or 32
};

class Pso : public GridPlanner {
 public:
  explicit Pso(PsoParams params = {}) : p_(params) {}
  std::string name() const override { return "pso"; }
  GridPlanResult solveGrid(const GridQuery& query, const StopToken& stop) override;

 private:
  PsoParams p_;
};

}  // namespace cosim
