#include <gtest/gtest.h>

#include <queue>

#include "planning/mapf/maze_generator.h"

using namespace cosim;

namespace {
// Number of free cells 4-connected to the free cell (0, 0).
int reachableFromOrigin(const OccupancyGrid& g) {
  std::vector<char> seen(g.cellCount(), 0);
  std::queue<Cell> q;
  q.push({0, 0, 0});
  seen[g.index(0, 0)] = 1;
  int count = 0;
  while (!q.empty()) {
    const Cell c = q.front();
    q.pop();
    ++count;
    const int d[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& s : d) {
      const Cell n{c.x + s[0], c.y + s[1], 0};
      if (g.free(n) && !seen[g.index(n)]) seen[g.index(n)] = 1, q.push(n);
    }
  }
  return count;
}
}  // namespace

TEST(MazeGenerator, FreeCellsAreAlwaysOneConnectedComponent) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed)
    for (const auto& [w, h] : std::vector<std::pair<int, int>>{{15, 15}, {75, 75}, {20, 9}}) {
      const OccupancyGrid g = generateMaze(w, h, seed);
      const int free_cells = static_cast<int>(g.cellCount() - g.blockedCount());
      ASSERT_EQ(reachableFromOrigin(g), free_cells) << w << "x" << h << " seed " << seed;
    }
}

TEST(MazeGenerator, NoTwoByTwoFreeBlockSoNoDiagonalMoveExists) {
  const OccupancyGrid g = generateMaze(31, 31, 7);
  for (int y = 0; y + 1 < g.ny(); ++y)
    for (int x = 0; x + 1 < g.nx(); ++x)
      EXPECT_TRUE(g.blocked(x, y) || g.blocked(x + 1, y) || g.blocked(x, y + 1) ||
                  g.blocked(x + 1, y + 1));
}

TEST(MazeGenerator, EvenCellsFreeOddOddCellsBlockedAndSeedDeterministic) {
  const OccupancyGrid a = generateMaze(15, 11, 3), b = generateMaze(15, 11, 3),
                      c = generateMaze(15, 11, 4);
  int differ = 0;
  for (int y = 0; y < a.ny(); ++y)
    for (int x = 0; x < a.nx(); ++x) {
      if (x % 2 == 0 && y % 2 == 0) {
        EXPECT_FALSE(a.blocked(x, y));
      }
      if (x % 2 == 1 && y % 2 == 1) {
        EXPECT_TRUE(a.blocked(x, y));
      }
      EXPECT_EQ(a.blocked(x, y), b.blocked(x, y));
      differ += a.blocked(x, y) != c.blocked(x, y);
    }
  EXPECT_GT(differ, 0);
  // A spanning tree over the 8 x 6 = 48 even cells: the corridors add at least 47 cells.
  EXPECT_GE(static_cast<int>(a.cellCount() - a.blockedCount()), 48 + 47);
}
