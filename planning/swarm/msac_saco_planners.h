#pragma once
// Registers the planners of seed 000 (Pěňčík 2014) by their scenario names: msac, saco,
// sacodm (grid planners) and rna, wf_rna, d_star_lite (navigation in an unknown map, registered as
// grid planners that navigate a static map seen through the robot's field of view).
#include "planning/planner_registry.h"
#include "planning/swarm/msac.h"
#include "planning/swarm/saco.h"

namespace cosim {

void registerAnt000Planners(PlannerRegistry& r);

// The parameters by the seed's names (snake_case), with the seed's defaults and ranges.
MsacParams readMsacParams(ParamSet& params);
SacoParams readSacoParams(ParamSet& params, const std::string& name);

}  // namespace cosim
