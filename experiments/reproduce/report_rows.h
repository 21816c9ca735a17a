#pragma once
// Cells that several reproductions put into the rows of NAME.json in the same shape, built in
// one place so that the same quantity has the same keys and units in every report.
#include <string>

#include "core/json_writer.h"
#include "experiments/reproduce/mapf_trial.h"
#include "experiments/reproduce/run_spread.h"

namespace cosim::reproduce {

// "<prefix>_s", "<prefix>_q1_s", "<prefix>_q3_s": the median and quartiles of run times given in
// milliseconds, written in seconds (the seeds' unit).
JsonObject& addSecondsSpread(JsonObject& row, const std::string& prefix, const Spread& ms);

// "instances", "success_percent", "mean_sum_of_costs" (NaN when no instance was solved): how a
// multi-robot planner did on repeated instances of one configuration.
JsonObject& addMapfOutcome(JsonObject& row, const MapfTrialSummary& s);

}  // namespace cosim::reproduce
