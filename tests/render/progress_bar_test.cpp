// Progress lines give durations a reader takes in at a glance.
#include "render/progress_bar.h"

#include <gtest/gtest.h>

using namespace cosim;

TEST(ProgressBar, DurationsReadAsSecondsMinutesOrHours) {
  EXPECT_EQ(durationText(42.4), "42 s");
  EXPECT_EQ(durationText(65.0), "1 min 05 s");
  EXPECT_EQ(durationText(2.0 * 3600 + 7 * 60 + 30), "2 h 07 min");
  EXPECT_EQ(durationText(-3.0), "0 s");
}
