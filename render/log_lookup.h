#pragma once
// Looking things up in a run log by time, and the tracking error the renderer and the figures
// colour by (the same definition as the metrics: sim/flight_metrics.h).
#include <cstddef>
#include <vector>

#include "sim/run_log.h"

namespace cosim {

// Index of the last sample at or before t (0 if t precedes the first); samples are in time order.
std::size_t sampleIndexAt(const VehicleLog& v, double t);

// Position error of every sample: against the reference trajectory when the reference is
// time-parametrised, else the distance to the planned path (the reference then jumps between
// waypoints, so the distance to it says nothing about tracking).
std::vector<double> trackingErrors(const VehicleLog& v, bool against_trajectory);

// The time of the last sample over all vehicles.
double logEndTime(const RunLog& log);

}  // namespace cosim
