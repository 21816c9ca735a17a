#include "experiments/reproduce/run_spread.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace cosim::reproduce {

namespace {
double quantile(const std::vector<double>& sorted, double p) {
  const double h = p * static_cast<double>(sorted.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}
}  // namespace

Spread spreadOf(std::vector<double> values) {
  Spread s;
  s.n = values.size();
  if (values.empty()) {
    s.mean = s.median = s.q1 = s.q3 = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / static_cast<double>(values.size());
  s.median = quantile(values, 0.5);
  s.q1 = quantile(values, 0.25);
  s.q3 = quantile(values, 0.75);
  return s;
}

std::string medianAndIqr(const Spread& s, int decimals) {
  if (s.n == 0) return "-";
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.*f [%.*f-%.*f]", decimals, s.median, decimals, s.q1, decimals,
                s.q3);
  return buf;
}

}  // namespace cosim::reproduce
