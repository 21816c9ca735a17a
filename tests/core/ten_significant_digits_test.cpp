// The one way cosim writes numbers into the MJCF it composes (world, vehicles, URDF conversion,
// moving obstacles): ten significant digits, as std::ostream writes them at precision 10.
#include <gtest/gtest.h>

#include <string>

#include "core/decimal_text.h"

namespace cosim {
namespace {

TEST(TenSignificantDigits, WritesDecimalsShortAndCutsAtTheTenthDigit) {
  EXPECT_EQ(tenSignificantDigits(0.1), "0.1");
  EXPECT_EQ(tenSignificantDigits(0.5 * 0.3), "0.15");
  EXPECT_EQ(tenSignificantDigits(1.0 / 3.0), "0.3333333333");
  EXPECT_EQ(tenSignificantDigits(12345.6789), "12345.6789");
  EXPECT_EQ(tenSignificantDigits(2.0), "2");
  EXPECT_EQ(tenSignificantDigits(-0.002), "-0.002");
  EXPECT_EQ(tenSignificantDigits(1e-5), "1e-05");
  EXPECT_EQ(tenSignificantDigits(123456789012.0), "1.23456789e+11");
}

}  // namespace
}  // namespace cosim
