#pragma once
#include "experiments/bench/bench_section.h"

namespace cosim::bench {

// Sweep throughput: the same short flights run (a) one by one as separate `cosim run` processes,
// (b) by the sweep runner with --jobs 1 (its overhead: target < 5 % of job time) and (c) with
// --jobs 2 (parallel speed-up on 2 cores: target >= 1.8x). Runs the jobs with this program
// (/proc/self/exe), so it belongs to the cosim binary.
Section benchSweepThroughput(bool quick);

}  // namespace cosim::bench
