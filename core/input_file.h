#pragma once
// Reading a user's input file whole, safely: only a regular file (a device such as /dev/zero
// would be read forever, a FIFO blocks until someone writes to it) and only up to a size that
// suits what the file is, so that a wrong path can neither hang the program nor fill memory.
#include <cstdint>
#include <string>

namespace cosim {

// Whole-file size limits, by kind of file (a file past its limit is surely a mistake).
constexpr std::uintmax_t kMaxScenarioFileBytes = 64u << 20;  // YAML scenarios and sweeps
constexpr std::uintmax_t kMaxModelFileBytes = 64u << 20;     // URDF, MJCF models and fragments
// A MovingAI map of the largest grid (OccupancyGrid::kMaxCells = 2^28 cells) plus its line ends.
constexpr std::uintmax_t kMaxMapFileBytes = 300u << 20;
// A run's CSV logs (cosim render): 1.1 million rows of timeseries.csv, read into about 370 MB
// of samples (a 20-robot, 182 s team run logs 85 MB; the default flight 21 MB).
constexpr std::uintmax_t kMaxLogFileBytes = 512u << 20;

// Throws InputError(path, "", problem) unless `path` names a regular file (symbolic links
// followed) of at most `max_bytes`; `what` names the file's role in the message ("scenario
// file", "URDF file"). Reads nothing.
void checkInputFile(const std::string& path, std::uintmax_t max_bytes, const std::string& what);

// checkInputFile, then the file's bytes.
std::string readInputFile(const std::string& path, std::uintmax_t max_bytes,
                          const std::string& what);

}  // namespace cosim
