#pragma once
// Registers the ant colonies of seed 000 (Pěňčík 2014) by their scenario names: msac, saco and
// sacodm, grid planners on the 8-connected AntGridView. RNA, the navigator that re-plans with
// MSAC, is registered with the other navigators (planning/navigation/navigation_planners.h).
#include <string>

#include "planning/planner_registry.h"
#include "planning/swarm/msac.h"
#include "planning/swarm/saco.h"

namespace cosim {

void registerMsacSacoPlanners(PlannerRegistry& r);

// The parameters by the seed's names (snake_case), with the seed's defaults and ranges.
MsacParams readMsacParams(ParamSet& params);
SacoParams readSacoParams(ParamSet& params, const std::string& name);
// conditional_diagonal (default true): a diagonal step needs both side cells free.
bool readConditionalDiagonal(ParamSet& params);

}  // namespace cosim
