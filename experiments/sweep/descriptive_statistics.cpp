#include "experiments/sweep/descriptive_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cosim {

double studentT975(std::size_t df) {
  // Exact table for small samples (the usual case: a handful of seeds per group).
  static const double table[] = {
      12.7062, 4.30265, 3.18245, 2.77645, 2.57058, 2.44691, 2.36462, 2.30600, 2.26216, 2.22814,
      2.20099, 2.17881, 2.16037, 2.14479, 2.13145, 2.11991, 2.10982, 2.10092, 2.09302, 2.08596,
      2.07961, 2.07387, 2.06866, 2.06390, 2.05954, 2.05553, 2.05183, 2.04841, 2.04523, 2.04227};
  if (df == 0) return std::numeric_limits<double>::quiet_NaN();
  if (df <= 30) return table[df - 1];
  // Cornish-Fisher expansion about the normal quantile (Abramowitz & Stegun 26.7.5); error
  // below 1e-4 for df > 30.
  const double z = 1.959963985, v = static_cast<double>(df);
  const double z3 = z * z * z, z5 = z3 * z * z;
  return z + (z3 + z) / (4 * v) + (5 * z5 + 16 * z3 + 3 * z) / (96 * v * v);
}

Descriptive describeSample(std::vector<double> x) {
  Descriptive d;
  d.n = x.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (x.empty()) {
    d.mean = d.sd = d.median = d.ci95_low = d.ci95_high = nan;
    return d;
  }
  double sum = 0;
  for (double v : x) sum += v;
  d.mean = sum / static_cast<double>(d.n);
  std::sort(x.begin(), x.end());
  d.median = d.n % 2 ? x[d.n / 2] : 0.5 * (x[d.n / 2 - 1] + x[d.n / 2]);
  if (d.n < 2) {
    d.sd = d.ci95_low = d.ci95_high = nan;
    return d;
  }
  double ss = 0;
  for (double v : x) ss += (v - d.mean) * (v - d.mean);
  d.sd = std::sqrt(ss / static_cast<double>(d.n - 1));
  const double half = studentT975(d.n - 1) * d.sd / std::sqrt(static_cast<double>(d.n));
  d.ci95_low = d.mean - half;
  d.ci95_high = d.mean + half;
  return d;
}

}  // namespace cosim
