#pragma once
#include "experiments/bench/bench_section.h"

namespace cosim::bench {

// The ant planners (by registry name, with parameter variants) against optimal A* on MovingAI
// maps (no corner cutting): mean optimality gap, time per query and its ratio to A*'s, success
// rate. Target for the best ant planner: mean gap < 2% at <= 10x A*'s time.
Section benchAntPlanners(bool quick);

}  // namespace cosim::bench
