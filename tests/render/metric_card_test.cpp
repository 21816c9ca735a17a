// index.html's headline cards: rounded to sensible digits in a unit a reader uses.
#include "render/metric_card.h"

#include <gtest/gtest.h>

using namespace cosim;

TEST(MetricCard, RoundsSecondsToHundredthsAndSmallLengthsToCentimetres) {
  EXPECT_EQ(cardValue("flight_time_s", "29.23000000001274"), "29.23 s");
  EXPECT_EQ(cardValue("rmse_m", "0.04465849305871672"), "4.47 cm");
  EXPECT_EQ(cardValue("min_clearance_m", "0.396"), "39.6 cm");
  EXPECT_EQ(cardValue("max_error_m", "0.0012345"), "0.123 cm");
  EXPECT_EQ(cardValue("planned_length_m", "45.678912"), "45.68 m");
  EXPECT_EQ(cardValue("planning_time_ms", "12.3456"), "12.3 ms");
  EXPECT_EQ(cardValue("flight_time_s", "30"), "30.00 s");
}

TEST(MetricCard, LeavesCountsFlagsAndWordsAsTheyAre) {
  EXPECT_EQ(cardValue("collisions", "3"), "3");
  EXPECT_EQ(cardValue("reached_goal", "true"), "true");
  EXPECT_EQ(cardValue("planner", "theta_star"), "theta_star");
  EXPECT_EQ(cardValue("rmse_m", "null"), "null");
}
