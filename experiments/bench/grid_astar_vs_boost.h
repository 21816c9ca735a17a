#pragma once
#include "experiments/bench/bench_section.h"

namespace cosim::bench {

// Our grid A* against Boost.Graph's astar_search on the same graph (a compressed sparse row
// graph of the free cells and legal moves, same octile heuristic), on the largest MovingAI map
// available and on a 3D grid of 200 x 200 x 50 cells: total time and expansions per second, as
// ratios (target >= 3x), and path lengths that must be identical.
Section benchGridAStarVsBoost(bool quick);

}  // namespace cosim::bench
