#pragma once
// Mean, sample standard deviation, median and the 95 % confidence interval of the mean
// (Student's t with n - 1 degrees of freedom: mean +- t * sd / sqrt(n)) of a sample.
#include <cstddef>
#include <vector>

namespace cosim {

struct Descriptive {
  std::size_t n = 0;
  double mean = 0, sd = 0, median = 0;  // sd: NaN when n < 2
  double ci95_low = 0, ci95_high = 0;   // NaN when n < 2
};

Descriptive describeSample(std::vector<double> values);

// The two-sided 95 % quantile t(0.975, df) of Student's t distribution (df >= 1).
double studentT975(std::size_t df);

}  // namespace cosim
