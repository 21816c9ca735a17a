#pragma once
// Single-agent A* on the MAPF grid, ignoring time (seed 004 Algorithm 4.2.1, ZNAJDZDROGĘ): the
// building block of independent A* and Local Repair A*. Optional extra blocked cells (the robots
// LRA* currently sees next to it) and heuristic noise (LRA*'s "agitation", Silver 2005 §2).
#include <cstdint>
#include <random>
#include <vector>

#include "core/stop_token.h"
#include "planning/mapf/mapf_grid.h"

namespace cosim {

struct SpatialAStarRequest {
  int start = 0, goal = 0;
  const std::vector<std::uint8_t>* extra_blocked = nullptr;  // per cell, 1 = blocked
  double noise = 0.0;                                        // each node's h gets + noise * U(0, 1)
  std::mt19937_64* rng = nullptr;                            // required when noise > 0
  const StopToken* deadline = nullptr;
};

struct SpatialAStarResult {
  std::vector<int> cells;  // start ... goal; empty when there is no path
  long expansions = 0;
};

SpatialAStarResult spatialAStar(const MapfGrid& grid, const SpatialAStarRequest& request);

}  // namespace cosim
