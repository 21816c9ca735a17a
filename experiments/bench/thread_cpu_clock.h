#pragma once
// Thread CPU time for benchmarks: the machine is shared, and wall time would count the other
// processes' time while a query is preempted.
#include <ctime>

namespace cosim::bench {

inline double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

}  // namespace cosim::bench
