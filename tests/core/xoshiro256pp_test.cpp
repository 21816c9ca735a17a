#include "core/xoshiro256pp.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/ziggurat_normal.h"

using namespace cosim;

// From the state {1, 2, 3, 4}: the first output is rotl(1 + 4, 23) + 1 = 5 * 2^23 + 1, and the
// next ones follow from the state transition (shift 17, rotation 45) as the authors' reference
// code (prng.di.unimi.it, xoshiro256plusplus.c) gives them.
TEST(Xoshiro256pp, GivesTheReferenceOutputsFromAKnownState) {
  Xoshiro256pp g = Xoshiro256pp::fromState({1, 2, 3, 4});
  EXPECT_EQ(g(), 41943041u);
  EXPECT_EQ(g(), 58720359u);
  EXPECT_EQ(g(), 3588806011781223u);
  EXPECT_EQ(g(), 3591011842654386u);
  EXPECT_EQ(g(), 9228616714210784205u);
}

// One seed, one stream; another seed word, another stream.
TEST(Xoshiro256pp, SeedSequenceGivesTheSameStreamForTheSameSeedOnly) {
  std::seed_seq a{1u, 0u, 7u}, b{1u, 0u, 7u}, c{1u, 0u, 8u};
  Xoshiro256pp ga(a), gb(b), gc(c);
  for (int i = 0; i < 4; ++i) {
    const auto x = ga();
    EXPECT_EQ(x, gb());
    EXPECT_NE(x, gc());
  }
}

// Through the ziggurat, 200 000 normal draws have mean 0 and variance 1 within four standard
// errors (2.2e-3 for the mean, 3.2e-3 for the variance) and 4.55 % of them beyond 2 sigma.
TEST(Xoshiro256pp, FeedsTheZigguratWithUnbiasedNormals) {
  std::seed_seq seq{42u};
  Xoshiro256pp g(seq);
  ZigguratNormal normal;
  const int n = 200000;
  double sum = 0.0, sum2 = 0.0;
  int beyond = 0;
  for (int i = 0; i < n; ++i) {
    const double x = normal(g);
    sum += x;
    sum2 += x * x;
    beyond += std::abs(x) > 2.0;
  }
  const double mean = sum / n, var = sum2 / n - mean * mean;
  EXPECT_NEAR(mean, 0.0, 4 * 1.0 / std::sqrt(n));
  EXPECT_NEAR(var, 1.0, 4 * std::sqrt(2.0 / n));
  EXPECT_NEAR(static_cast<double>(beyond) / n, 0.0455, 4 * std::sqrt(0.0455 * 0.9545 / n));
}
