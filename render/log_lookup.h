#pragma once
// Looking things up in a run log by time. What a vehicle's tracking error is measured against
// (sim/error_reference.h) and its per-sample errors come from the run's record
// (run/record/run_record.h), as the evaluation measured them.
#include <cstddef>

#include "sim/error_reference.h"
#include "sim/run_log.h"

namespace cosim {

// Index of the last sample at or before t (0 if t precedes the first); samples are in time order.
std::size_t sampleIndexAt(const VehicleLog& v, double t);

// The time of the last sample over all vehicles.
double logEndTime(const RunLog& log);

}  // namespace cosim
