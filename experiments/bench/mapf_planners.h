#pragma once
#include "experiments/bench/bench_section.h"

namespace cosim::bench {

// WHCA* (window 8, dynamic priorities) against CBS (optimal) on the same MAPF instances:
// random-32-32-10 and warehouse-10-20-10-2-1, first N agents of -random-1.scen. Planning time
// per agent count, the CBS / WHCA* time ratio and the WHCA* / CBS sum-of-costs ratio at 20
// agents. Targets: WHCA* plans 100 agents on the 32 x 32 map in < 100 ms; CBS solves the
// 20-agent instances within 1 s.
Section benchMapfPlanners(bool quick);

}  // namespace cosim::bench
