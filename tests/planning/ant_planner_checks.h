#pragma once
// Checks shared by the tests of the 8-connected ant planners of seed 000 (MSAC, SACO) and the
// navigators.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "planning/grid/grid_planner.h"

namespace cosim::test {

inline GridQuery antQuery(const OccupancyGrid& g, Cell s, Cell t, std::uint64_t seed = 1) {
  GridQuery q;
  q.grid = &g;
  q.start = s;
  q.goal = t;
  q.seed = seed;
  return q;
}

// Every cell is free and every consecutive pair is one legal move (no corner cut when
// `conditional` diagonals are asked for).
inline void expectLegalCellPath(const OccupancyGrid& g, const std::vector<Cell>& cells,
                                bool conditional) {
  for (std::size_t i = 0; i < cells.size(); ++i) {
    EXPECT_FALSE(g.blocked(cells[i])) << "cell " << i;
    if (i == 0) continue;
    const GridStep s{cells[i].x - cells[i - 1].x, cells[i].y - cells[i - 1].y,
                     cells[i].z - cells[i - 1].z, 0.0};
    ASSERT_LE(std::max({std::abs(s.dx), std::abs(s.dy), std::abs(s.dz)}), 1) << "step " << i;
    EXPECT_TRUE(gridStepAllowed(g, cells[i - 1], s, !conditional)) << "step " << i;
  }
}

}  // namespace cosim::test
