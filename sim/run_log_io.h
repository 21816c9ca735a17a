#pragma once
// The run log on disk: timeseries.csv (one row per vehicle per control step), path.csv (the
// planned waypoints) and, in runs with moving obstacles, moving_obstacles.csv (t, name, x, y,
// z: each obstacle's centre at each logged instant). `cosim render` reads them back to
// re-render without re-simulating.
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sim/run_log.h"

namespace cosim {

std::string timeseriesCsv(const RunLog& log);
// The numeric columns of timeseries.csv for log.vehicles[vehicle] (throws std::out_of_range past
// the last vehicle), by header name in the file's order, one value per sample: the same column
// definitions as the file (the vehicle's name, a text column, is left out).
std::vector<std::pair<std::string, std::vector<double>>> timeseriesColumns(const RunLog& log,
                                                                           std::size_t vehicle);
std::string pathCsv(const RunLog& log);
std::string movingObstaclesCsv(const RunLog& log);

// What a log read back may hold: what the scenario's run could have logged (logBoundsFor in
// sim/scenario.h), so that a doctored file can neither fill memory nor stretch the video.
struct LogBounds {
  double max_time = std::numeric_limits<double>::infinity();  // s: every t in [0, max_time]
  std::size_t max_rows_per_vehicle = std::numeric_limits<std::size_t>::max();
  std::size_t max_vehicles = std::numeric_limits<std::size_t>::max();
  std::size_t max_moving_obstacles = std::numeric_limits<std::size_t>::max();
  std::size_t max_path_points = std::numeric_limits<std::size_t>::max();
  // The rows the run wrote (run.json), where known: a log cut at a line boundary still parses.
  std::optional<std::size_t> timeseries_rows, path_rows;
  // NaN or infinity in a row: only a run that diverged (end_reason) logs them.
  bool non_finite_allowed = false;
};

// Reads what timeseriesCsv/pathCsv wrote into `log` (samples and planned paths per vehicle, in
// order of first appearance), streaming: memory holds the samples, never the file. Throws
// InputError naming the file and line on malformed input, a time outside [0, max_time], going
// backwards or repeated, a value that is not finite, no rows, and more or fewer rows than
// `bounds` allow.
void readTimeseriesCsv(const std::string& path, RunLog& log, const LogBounds& bounds = {});
void readPathCsv(const std::string& path, RunLog& log, const LogBounds& bounds = {});
// Appends the obstacles of moving_obstacles.csv to log.moving_obstacles (in order of first
// appearance; their radius is not in the file and stays 0). Throws InputError as above.
void readMovingObstaclesCsv(const std::string& path, RunLog& log, const LogBounds& bounds = {});

}  // namespace cosim
