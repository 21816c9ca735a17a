#include <gtest/gtest.h>

#include "mapf_test_instances.h"
#include "planning/mapf/solution_validator.h"

using namespace cosim;
using cosim::test::instanceFrom;

namespace {
MapfInstance twoByTwo(int connectivity, std::vector<Cell> starts, std::vector<Cell> goals) {
  return instanceFrom({"..", ".."}, std::move(starts), std::move(goals), connectivity);
}
}  // namespace

TEST(MapfSolutionValidator, AcceptsConflictFreeSolutionWithFollowing) {
  // Agent 1 enters (1,0) in the same step agent 0 leaves it: following is allowed.
  const auto inst = instanceFrom({"...."}, {{1, 0, 0}, {0, 0, 0}}, {{3, 0, 0}, {2, 0, 0}});
  const auto v = validateMapfSolution(
      inst, {{{1, 0, 0}, {2, 0, 0}, {3, 0, 0}}, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}});
  EXPECT_TRUE(v.valid());
}

TEST(MapfSolutionValidator, FindsVertexConflict) {
  const auto inst = instanceFrom({"...", "..."}, {{0, 0, 0}, {2, 0, 0}}, {{1, 1, 0}, {1, 0, 0}});
  const auto v =
      validateMapfSolution(inst, {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{2, 0, 0}, {1, 0, 0}}});
  ASSERT_EQ(v.conflicts.size(), 1u);
  EXPECT_EQ(v.conflicts[0].kind, MapfConflict::Kind::kVertex);
  EXPECT_EQ(v.conflicts[0].t, 1);
  EXPECT_EQ(v.conflicts[0].cell, (Cell{1, 0, 0}));
}

TEST(MapfSolutionValidator, FindsSwapConflict) {
  const auto inst = instanceFrom({".."}, {{0, 0, 0}, {1, 0, 0}}, {{1, 0, 0}, {0, 0, 0}});
  const auto v = validateMapfSolution(inst, {{{0, 0, 0}, {1, 0, 0}}, {{1, 0, 0}, {0, 0, 0}}});
  ASSERT_EQ(v.conflicts.size(), 1u);
  EXPECT_EQ(v.conflicts[0].kind, MapfConflict::Kind::kSwap);
  EXPECT_EQ(v.conflicts[0].t, 0);
}

TEST(MapfSolutionValidator, FindsCrossingDiagonalsOnEightConnectedGrid) {
  const auto inst = twoByTwo(8, {{0, 0, 0}, {1, 0, 0}}, {{1, 1, 0}, {0, 1, 0}});
  const auto v = validateMapfSolution(inst, {{{0, 0, 0}, {1, 1, 0}}, {{1, 0, 0}, {0, 1, 0}}});
  ASSERT_EQ(v.conflicts.size(), 1u);
  EXPECT_EQ(v.conflicts[0].kind, MapfConflict::Kind::kCrossingDiagonal);
}

TEST(MapfSolutionValidator, AgentParkedOnItsGoalBlocksLaterPassers) {
  // Agent 0 arrives at (1,0) at t=1 and stays; agent 1 passes through (1,0) at t=2.
  const auto inst = instanceFrom({"...", "..."}, {{0, 0, 0}, {2, 1, 0}}, {{1, 0, 0}, {0, 0, 0}});
  const auto v = validateMapfSolution(
      inst, {{{0, 0, 0}, {1, 0, 0}}, {{2, 1, 0}, {2, 0, 0}, {1, 0, 0}, {0, 0, 0}}});
  ASSERT_EQ(v.conflicts.size(), 1u);
  EXPECT_EQ(v.conflicts[0].t, 2);
  EXPECT_EQ(v.conflicts[0].agent_a, 0);
}

TEST(MapfSolutionValidator, RejectsDiagonalOnFourConnectedGridAndPastWallCorner) {
  const auto four = twoByTwo(4, {{0, 0, 0}}, {{1, 1, 0}});
  EXPECT_EQ(validateMapfSolution(four, {{{0, 0, 0}, {1, 1, 0}}}).problems.size(), 1u);
  const auto corner = instanceFrom({".@", ".."}, {{0, 0, 0}}, {{1, 1, 0}}, 8);
  EXPECT_EQ(validateMapfSolution(corner, {{{0, 0, 0}, {1, 1, 0}}}).problems.size(), 1u);
  const auto open = twoByTwo(8, {{0, 0, 0}}, {{1, 1, 0}});
  EXPECT_TRUE(validateMapfSolution(open, {{{0, 0, 0}, {1, 1, 0}}}).valid());
}

TEST(MapfSolutionValidator, RejectsWrongStartGoalJumpsAndBlockedCells) {
  const auto inst = instanceFrom({"..@."}, {{0, 0, 0}}, {{1, 0, 0}});
  EXPECT_FALSE(validateMapfSolution(inst, {{{1, 0, 0}}}).valid());             // wrong start
  EXPECT_FALSE(validateMapfSolution(inst, {{{0, 0, 0}}}).valid());             // wrong goal
  EXPECT_FALSE(validateMapfSolution(inst, {{{0, 0, 0}, {3, 0, 0}}}).valid());  // jump
  EXPECT_FALSE(validateMapfSolution(inst, {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 0, 0}}})
                   .valid());                            // blocked
  EXPECT_FALSE(validateMapfSolution(inst, {}).valid());  // missing
}

TEST(MapfSolutionValidator, ThreeDimensionalMovesFollowTheConnectivity) {
  MapfInstance inst;
  inst.grid = OccupancyGrid(2, 2, 2);
  inst.starts = {{0, 0, 0}};
  inst.goals = {{1, 1, 1}};
  const std::vector<MapfPath> diagonal = {{{0, 0, 0}, {1, 1, 1}}};
  inst.connectivity = 26;
  EXPECT_TRUE(validateMapfSolution(inst, diagonal).valid());
  for (const int connectivity : {6, 18}) {
    inst.connectivity = connectivity;
    const auto v = validateMapfSolution(inst, diagonal);
    ASSERT_EQ(v.problems.size(), 1u) << connectivity;
    EXPECT_NE(v.problems[0].find("step along 3 axes"), std::string::npos) << v.problems[0];
  }
  // No corner cutting in 3D: the space diagonal needs all six other cells of the cube free.
  inst.connectivity = 26;
  inst.grid.setBlocked(0, 1, 1, true);
  const auto cut = validateMapfSolution(inst, diagonal);
  ASSERT_EQ(cut.problems.size(), 1u);
  EXPECT_NE(cut.problems[0].find("past a wall corner from (0, 0, 0)"), std::string::npos);
}

TEST(MapfSolutionValidator, ThreeDimensionalSwapsCrossingsAndSharedCells) {
  MapfInstance inst;
  inst.grid = OccupancyGrid(2, 2, 2);
  inst.connectivity = 26;
  // Two space diagonals of one cube cross at its centre.
  inst.starts = {{0, 0, 0}, {1, 0, 0}};
  inst.goals = {{1, 1, 1}, {0, 1, 1}};
  auto v = validateMapfSolution(inst, {{{0, 0, 0}, {1, 1, 1}}, {{1, 0, 0}, {0, 1, 1}}});
  ASSERT_EQ(v.conflicts.size(), 1u);
  EXPECT_EQ(v.conflicts[0].kind, MapfConflict::Kind::kCrossingDiagonal);
  // A vertical swap.
  inst.starts = {{0, 0, 0}, {0, 0, 1}};
  inst.goals = {{0, 0, 1}, {0, 0, 0}};
  v = validateMapfSolution(inst, {{{0, 0, 0}, {0, 0, 1}}, {{0, 0, 1}, {0, 0, 0}}});
  ASSERT_EQ(v.conflicts.size(), 1u);
  EXPECT_EQ(v.conflicts[0].kind, MapfConflict::Kind::kSwap);
  // Two agents in one cell of the upper floor; the same x, y on different floors is no conflict.
  inst.starts = {{0, 0, 0}, {1, 1, 1}};
  inst.goals = {{0, 1, 1}, {0, 0, 1}};
  v = validateMapfSolution(inst, {{{0, 0, 0}, {0, 1, 1}}, {{1, 1, 1}, {0, 1, 1}, {0, 0, 1}}});
  ASSERT_EQ(v.conflicts.size(), 1u);
  EXPECT_EQ(v.conflicts[0].kind, MapfConflict::Kind::kVertex);
  EXPECT_EQ(v.conflicts[0].cell, (Cell{0, 1, 1}));
  inst.starts = {{0, 0, 0}, {0, 0, 1}};
  inst.goals = {{1, 0, 0}, {1, 0, 1}};
  EXPECT_TRUE(validateMapfSolution(inst, {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {1, 0, 1}}}).valid());
}
