#include "experiments/reproduce/report_rows.h"

#include <cmath>

namespace cosim::reproduce {

JsonObject& addSecondsSpread(JsonObject& row, const std::string& prefix, const Spread& ms) {
  return row.add(prefix + "_s", ms.median / 1000.0)
      .add(prefix + "_q1_s", ms.q1 / 1000.0)
      .add(prefix + "_q3_s", ms.q3 / 1000.0);
}

JsonObject& addMapfOutcome(JsonObject& row, const MapfTrialSummary& s) {
  return row.add("instances", s.runs)
      .add("success_percent", s.successPercent())
      .add("mean_sum_of_costs", s.solved ? s.meanSumOfCosts() : NAN);
}

}  // namespace cosim::reproduce
