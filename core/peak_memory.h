#pragma once
// The process's peak resident memory so far (getrusage's ru_maxrss, which Linux reports in
// kilobytes): what a benchmark row can say about memory without instrumenting every allocation.
// It never decreases, so in a run of several instances it is the largest so far.
#include <cstddef>

namespace cosim {

std::size_t peakResidentBytes();

}  // namespace cosim
