// cosim identify on a real thrust stand (IMRCLab's Crazyflie 2.1 Brushless, tests/data/
// crazyflie/README): the CSV with units in its header is read as a user's would be, and the
// thrust constant models/cf21_brushless_identified.yaml holds comes out of it again.
#include <gtest/gtest.h>

#include "experiments/identify/identification.h"

using namespace cosim;

TEST(IdentifyRealData, TheBrushlessThrustStandGivesTheCommittedThrustConstant) {
  const IdentificationLog stand = readIdentificationLog(
      std::string(COSIM_TEST_DATA_DIR) + "/crazyflie/cf21bl_guards_thrust_stand.csv");
  EXPECT_EQ(stand.rows, 72u);
  ASSERT_TRUE(stand.has("thrust") && stand.has("pwm4") && stand.t.empty());
  // 97 g-force at the row with PWM 64861: the unit in the header ("thrust[g]") is applied.
  EXPECT_NEAR(stand.column("thrust")[0], 0.097 * 9.80665, 1e-12);
  const IdentificationResult r = identify({stand}, IdentifyOptions{});
  ASSERT_TRUE(r.thrust_coefficient.identified);
  EXPECT_NEAR(r.thrust_coefficient.value, 3.91001e-8, 1e-12);
  EXPECT_NEAR(r.thrust_coefficient.ci_low, 3.89101e-8, 1e-12);
  EXPECT_NEAR(r.thrust_coefficient.residual, 0.0111115, 1e-6);
  // No time column: the stand's rows give the motor map directly, no lag, no flight values.
  EXPECT_TRUE(r.motor_speed[1].identified);
  EXPECT_FALSE(r.motor_delay.identified);
  EXPECT_FALSE(r.mass.identified);
}
