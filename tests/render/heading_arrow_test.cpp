// The heading arrow points where the vehicle is going, and disappears when it is still.
#include "render/heading_arrow.h"

#include <gtest/gtest.h>

using namespace cosim;

TEST(HeadingArrow, PointsAlongTheVelocityNotTheYaw) {
  // Flying sideways (+y) and climbing a little: the arrow follows the motion.
  const auto d = headingArrowDirection({0.0, 1.5, 0.5});
  ASSERT_TRUE(d.has_value());
  EXPECT_NEAR(d->x(), 0.0, 1e-12);
  EXPECT_NEAR(d->y(), 1.5 / std::sqrt(2.5), 1e-12);
  EXPECT_NEAR(d->z(), 0.5 / std::sqrt(2.5), 1e-12);
}

TEST(HeadingArrow, HiddenWhenNearlyStill) {
  EXPECT_FALSE(headingArrowDirection({0.03, 0.04, 0.0}).has_value());  // 5 cm/s: hovering
  EXPECT_FALSE(headingArrowDirection(Eigen::Vector3d::Zero()).has_value());
  EXPECT_TRUE(headingArrowDirection({0.0, 0.0, -0.2}).has_value());  // descending
}
