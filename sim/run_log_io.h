#pragma once
// The run log on disk: timeseries.csv (one row per vehicle per control step) and path.csv (the
// planned waypoints). `cosim render` reads them back to re-render without re-simulating.
#include <string>
#include <vector>

#include "sim/run_log.h"

namespace cosim {

std::string timeseriesCsv(const RunLog& log);
std::string pathCsv(const RunLog& log);

// Reads what timeseriesCsv/pathCsv wrote into `log` (samples and planned paths per vehicle, in
// order of first appearance). Throws InputError naming the file and line on malformed input.
void readTimeseriesCsv(const std::string& path, RunLog& log);
void readPathCsv(const std::string& path, RunLog& log);

}  // namespace cosim
