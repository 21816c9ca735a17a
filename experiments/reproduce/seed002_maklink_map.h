#pragma once
// The MAKLINK example map of seed 002, part B, rebuilt. The seed's map (Tan, He and Sloman 2007,
// Acta Automatica Sinica 33: 279-285) is not in its text; what the text states is its structure
// and scale: l = 26 free lines, Dijkstra's midpoint path crossing d = 9 of them and 507.692 m long,
// the ACS optimum 440.233 m. Ours: seven convex quadrilaterals (taken as already grown) between a
// start and a goal near opposite corners, found by a random search over such layouts for one
// whose MAKLINK graph has exactly l = 26 and d = 9 and whose ACS / Dijkstra ratio is near the
// seed's 0.867, then scaled so that Dijkstra's path is 507.6 m (scaling changes no line count and
// no ratio; coordinates rounded to 0.1 m).
#include <Eigen/Core>

#include "planning/swarm/maklink_graph.h"

namespace cosim::reproduce {

struct Seed002MaklinkMap {
  MaklinkGraph graph;
  Eigen::Vector2d start, goal;
};

Seed002MaklinkMap seed002MaklinkMap();

}  // namespace cosim::reproduce
