#include "core/peak_memory.h"

#include <sys/resource.h>

namespace cosim {

std::size_t peakResidentBytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux: kilobytes
}

}  // namespace cosim
