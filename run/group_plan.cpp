#include "run/group_plan.h"

#include <algorithm>

namespace cosim {

PlanSummary summarizeSeparatePlans(const std::vector<VehiclePlan>& plans) {
  PlanSummary s;
  for (const VehiclePlan& p : plans) {
    s.time_ms += p.time_ms;
    for (const auto& [name, value] : p.counters) s.counters[name] += value;
    s.inflation = std::max(s.inflation, p.inflation);
  }
  if (!plans.empty()) s.params = plans.front().params;
  return s;
}

}  // namespace cosim
