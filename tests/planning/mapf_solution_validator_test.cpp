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
