#include "core/ziggurat_normal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

using namespace cosim;

TEST(ZigguratNormal, LayersHaveEqualAreaAndCloseAtThePeak) {
  const auto f = [](double x) { return std::exp(-0.5 * x * x); };
  // The paper's v for 256 layers.
  EXPECT_NEAR(ZigguratNormal::layerArea(), 4.92867323399e-3, 1e-13);
  EXPECT_DOUBLE_EQ(ZigguratNormal::edge(1), 3.6541528853610088);
  // Every rectangle above the base has area v; the last, from x[255] to the peak, too: a wrong
  // r would leave it too wide or too narrow.
  for (int i = 1; i < ZigguratNormal::kLayers; ++i) {
    const double top = i + 1 < ZigguratNormal::kLayers ? f(ZigguratNormal::edge(i + 1)) : 1.0;
    EXPECT_NEAR(ZigguratNormal::edge(i) * (top - f(ZigguratNormal::edge(i))),
                ZigguratNormal::layerArea(), 1e-12)
        << i;
  }
}

TEST(ZigguratNormal, MomentsAndTailsAreTheStandardNormals) {
  std::mt19937_64 engine(20260101);
  const ZigguratNormal normal;
  const int n = 2000000;
  double sum = 0.0, sq = 0.0, fourth = 0.0;
  int beyond1 = 0, beyond2 = 0, beyond_r = 0, beyond4 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = normal(engine);
    sum += x;
    sq += x * x;
    fourth += x * x * x * x;
    const double a = std::abs(x);
    beyond1 += a > 1.0;
    beyond2 += a > 2.0;
    beyond_r += a > 3.6541528853610088;  // drawn by the tail method only
    beyond4 += a > 4.0;
  }
  const double mean = sum / n;
  const double var = sq / n - mean * mean;
  // Tolerances about 4 standard errors of each estimate at n = 2e6.
  EXPECT_NEAR(mean, 0.0, 0.003);
  EXPECT_NEAR(var, 1.0, 0.004);
  EXPECT_NEAR(fourth / n, 3.0, 0.03);                   // kurtosis
  EXPECT_NEAR(beyond1 / double(n), 0.3173105, 0.0014);  // 2 (1 - Phi(1))
  EXPECT_NEAR(beyond2 / double(n), 0.0455003, 0.0006);  // 2 (1 - Phi(2))
  EXPECT_NEAR(beyond_r / double(n), 2.580e-4, 4.5e-5);  // 2 (1 - Phi(r))
  EXPECT_NEAR(beyond4 / double(n), 6.334e-5, 2.4e-5);   // 2 (1 - Phi(4)): the tail's shape
}

TEST(ZigguratNormal, SameEngineStateGivesTheSameNumbers) {
  std::mt19937_64 a(7), b(7), c(8);
  const ZigguratNormal normal;
  bool differs = false;
  for (int i = 0; i < 10000; ++i) {
    const double x = normal(a);
    EXPECT_EQ(x, normal(b));
    differs = differs || x != normal(c);
  }
  EXPECT_TRUE(differs);
}
