#pragma once
// Seed 002, part B: the hybrid ant colony system on a MAKLINK graph (after G.-Z. Tan, H. He,
// A. Sloman, "Ant colony system algorithm for real-time globally optimal path planning of mobile
// robots", Acta Automatica Sinica 33 (2007) 279-285). Dijkstra over the free lines' midpoints
// gives the first path S -> P1 ... Pd -> T; the ants then choose, line by line, one of `levels`
// evenly spaced offsets h in [0, 1] along each crossed line (the "nodes" n_ij), with the
// pseudo-random proportional rule (q <= q0: argmax tau * eta^beta; else the roulette of eq. 1),
// eta_ij = (1 + s - |h_j - y*_i|) / (1 + s) (s = 1 / (levels - 1): 1.1 / 1.1 for 11 levels; y*
// is the previous tour's best offset, and before the first tour all options are equally
// visible, so the first tour is not just Dijkstra's midpoints), the local
// update tau <- (1 - rho) tau + rho tau0 (eq. 3) after each choice and the global update
// tau <- (1 - rho) tau + rho / L+ on the best path's nodes (eq. 2) after each tour. It stops
// after NC tours or when all m ants built the same tour.
//
// As a world planner it works in the horizontal plane at the start's height: the obstacles that
// meet that plane are cut into grown convex polygons (planar_obstacles.h), the walls are the
// world's x-y bounds shrunk by the inflation; if the goal is at another height the path ends
// with a vertical segment to it, checked against the world.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/stop_token.h"
#include "planning/planner.h"
#include "planning/planner_registry.h"
#include "planning/swarm/maklink_graph.h"

namespace cosim {

struct AcsMaklinkParams {
  // The seed's values ("found experimentally to give good convergence").
  double beta = 2.0;
  double q0 = 0.85;
  double rho = 0.1;
  double tau0 = 0.0002;
  int ants = 10;         // m
  int iterations = 200;  // NC
  int levels = 11;       // offsets 0, 0.1, ..., 1 on each line
  int circle_sides = 8;  // polygon sides for cylinders and spheres
};

struct AcsMaklinkResult {
  bool success = false;
  PlannerStatus status = PlannerStatus::Unknown;
  std::string message;
  std::vector<Eigen::Vector2d> path;  // S, P1(h1), ..., Pd(hd), T
  std::vector<double> offsets;        // h1* ... hd*
  double dijkstra_length = 0.0;       // the midpoint path
  double length = 0.0;
  int lines = 0;                // l, free lines in the graph
  int crossed = 0;              // d
  int iterations = 0;           // tours run
  int best_iteration = 0;       // tour in which the final best was found (0: Dijkstra's path)
  std::vector<double> history;  // length of T+ after each tour
  double time_ms = 0.0;
};

// The planner on a ready graph (used by the world planner, the reproduction and the tests).
AcsMaklinkResult optimiseMaklinkRoute(const MaklinkGraph& graph, const Eigen::Vector2d& start,
                                      const Eigen::Vector2d& goal, const AcsMaklinkParams& params,
                                      std::uint64_t seed, const StopToken& deadline);

class AcsMaklink : public Planner {
 public:
  explicit AcsMaklink(AcsMaklinkParams params = {}) : p_(params) {}
  std::string name() const override { return "acs_maklink"; }
  PlanResult solve(const PlanningProblem& problem, const StopToken& stop) override;

 private:
  AcsMaklinkParams p_;
};

void registerAcsMaklinkPlanner(PlannerRegistry& r);

}  // namespace cosim
