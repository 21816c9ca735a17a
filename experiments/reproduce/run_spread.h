#pragma once
// Repeated runs summarised by their median and interquartile range (the machine is shared and
// run times swing: a median with its spread says more than a mean), plus the mean for figures
// the seeds report as averages.
#include <string>
#include <vector>

namespace cosim::reproduce {

struct Spread {
  std::size_t n = 0;
  double mean = 0, median = 0, q1 = 0, q3 = 0;  // NaN for an empty sample
};

// Quartiles by linear interpolation between order statistics (Hyndman and Fan 1996, type 7,
// as R's and NumPy's defaults).
Spread spreadOf(std::vector<double> values);

// "12.3 [11.0-14.1]": the median and the interquartile range with the given decimals; "-" if
// the sample is empty.
std::string medianAndIqr(const Spread& s, int decimals);

}  // namespace cosim::reproduce
