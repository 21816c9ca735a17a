#include "planning/grid/movingai.h"

#include <gtest/gtest.h>

#include "core/input_error.h"

using namespace cosim;

TEST(MovingAIMap, ReadsDimensionsAndObstaclesOfRandom32) {
  const OccupancyGrid g = readMovingAIMap(COSIM_SOURCE_DIR "/experiments/maps/random-32-32-10.map");
  EXPECT_EQ(g.nx(), 32);
  EXPECT_EQ(g.ny(), 32);
  EXPECT_FALSE(g.is3D());
  // random-32-32-10 has 10% of its cells blocked (102 of 1024 in this instance).
  EXPECT_NEAR(static_cast<double>(g.blockedCount()) / 1024.0, 0.10, 0.01);
}

TEST(MovingAIMap, CrlfAndMissingFinalNewlineAreAccepted) {
  const OccupancyGrid g = parseMovingAIMap("type octile\r\nheight 2\r\nwidth 3\r\nmap\r\n.@.\r\nT..", "m");
  EXPECT_TRUE(g.blocked(1, 0));
  EXPECT_TRUE(g.blocked(0, 1));
  EXPECT_FALSE(g.blocked(2, 1));
  EXPECT_EQ(g.blockedCount(), 2u);
}

TEST(MovingAIMap, HugeHeaderIsRejectedBeforeAllocation) {
  EXPECT_THROW(parseMovingAIMap("type octile\nheight 1000000\nwidth 1000000\nmap\n", "m"),
               InputError);
}

TEST(MovingAIMap, ShortRowNamesItsLine) {
  try {
    parseMovingAIMap("type octile\nheight 2\nwidth 3\nmap\n...\n..\n", "bad.map");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bad.map");
    EXPECT_EQ(e.place(), "line 6");
  }
}

TEST(MovingAIScenario, ParsesTabSeparatedLinesWithOptimalLength) {
  const auto lines =
      readMovingAIScenario(COSIM_SOURCE_DIR "/experiments/maps/random-32-32-10-random-1.scen");
  ASSERT_GT(lines.size(), 10u);
  EXPECT_EQ(lines[0].width, 32);
  EXPECT_GT(lines[0].optimal_length, 0.0);
}

TEST(MovingAIScenario, OldSpaceSeparatedVariantParses) {
  const auto lines = parseMovingAIScenario("version 1.0\n0 a.map 4 4 0 0 3 3 4.24\n", "s");
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].goal_x, 3);
  EXPECT_DOUBLE_EQ(lines[0].optimal_length, 4.24);
}
