#include "sim/log_growth.h"

#include <algorithm>

namespace cosim {

std::size_t initialLogSamples(std::size_t expected, std::size_t vehicles) {
  const std::size_t share =
      kInitialLogBytes / (sizeof(LogSample) * std::max<std::size_t>(vehicles, 1));
  return std::min(expected, std::max(share, kMinInitialLogSamples));
}

void reserveLogSamples(std::vector<LogSample>& samples, std::size_t n) {
  // resize writes every sample; clear keeps the storage.
  samples.resize(n);
  samples.clear();
}

void growLogSamples(std::vector<LogSample>& samples) {
  const std::size_t n = samples.size();
  // Growing a full vector to 2n allocates exactly 2n (libstdc++ grows by max(size, added)) and
  // writes the new samples; shrinking back keeps the storage.
  samples.resize(std::max(2 * n, kMinInitialLogSamples));
  samples.resize(n);
}

}  // namespace cosim
