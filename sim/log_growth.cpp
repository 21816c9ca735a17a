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

void growLogSamples(std::vector<LogSample>& samples, std::size_t most) {
  const std::size_t n = samples.size();
  // reserve allocates exactly `target`; resize writes the new samples; shrinking back keeps the
  // storage. A log already at `most` (it should not pass it) is left to emplace_back's doubling.
  const std::size_t target = std::min(std::max(2 * n, kMinInitialLogSamples), most);
  if (target <= n) return;
  samples.reserve(target);
  samples.resize(target);
  samples.resize(n);
}

}  // namespace cosim
