#include "experiments/sweep/descriptive_statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>

namespace cosim {

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
  std::tie(d.ci95_low, d.ci95_high) = bootstrapMeanInterval95(x);
  return d;
}

std::pair<double, double> bootstrapMeanInterval95(const std::vector<double>& values,
                                                  std::size_t resamples) {
  // SplitMix64 (Steele, Lea and Flood 2014): the same stream on every platform, unlike the
  // standard library's distributions.
  std::uint64_t state = 0x5eed5eed5eed5eedULL;
  const auto next = [&state] {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  const std::size_t n = values.size();
  std::vector<double> means(resamples);
  for (double& mean : means) {
    double sum = 0;
    for (std::size_t k = 0; k < n; ++k) sum += values[next() % n];  // bias below 1e-17
    mean = sum / static_cast<double>(n);
  }
  std::sort(means.begin(), means.end());
  // Percentiles by linear interpolation between order statistics (Hyndman and Fan's type 7).
  const auto percentile = [&means](double p) {
    const double at = p * static_cast<double>(means.size() - 1);
    const std::size_t below = static_cast<std::size_t>(at);
    const std::size_t above = std::min(below + 1, means.size() - 1);
    return means[below] + (at - static_cast<double>(below)) * (means[above] - means[below]);
  };
  return {percentile(0.025), percentile(0.975)};
}

}  // namespace cosim
