#pragma once
// The run log on disk: timeseries.csv (one row per vehicle per control step), path.csv (the
// planned waypoints) and, in runs with moving obstacles, moving_obstacles.csv (t, name, x, y,
// z: each obstacle's centre at each logged instant). `cosim render` reads them back to
// re-render without re-simulating.
#include <string>
#include <vector>

#include "sim/run_log.h"

namespace cosim {

std::string timeseriesCsv(const RunLog& log);
std::string pathCsv(const RunLog& log);
std::string movingObstaclesCsv(const RunLog& log);

// Reads what timeseriesCsv/pathCsv wrote into `log` (samples and planned paths per vehicle, in
// order of first appearance). Throws InputError naming the file and line on malformed input.
void readTimeseriesCsv(const std::string& path, RunLog& log);
void readPathCsv(const std::string& path, RunLog& log);
// Appends the obstacles of moving_obstacles.csv to log.moving_obstacles (in order of first
// appearance; their radius is not in the file and stays 0). Throws InputError as above, also
// when an obstacle's times go backwards.
void readMovingObstaclesCsv(const std::string& path, RunLog& log);

}  // namespace cosim
