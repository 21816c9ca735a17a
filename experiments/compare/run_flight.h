#pragma once
// One vehicle's flight in a run folder written by `cosim run`, as compare-real needs it: its
// reference and flown positions at the control rate (timeseries.csv), the window the reference
// covers, and whether the scenario flew it relative to the vehicle's start
// (vehicles[i].reference.relative in the run's scenario.yaml).
#include <filesystem>
#include <string>

#include "experiments/compare/sampled_path.h"
#include "sim/run_log.h"

namespace cosim {

struct RunFlight {
  std::string vehicle;
  std::string timeseries_file;   // named in errors about the run's samples
  SampledPath reference, flown;  // on the same times
  // The reference's duration as samples [window_begin, window_end) of the time series: from the
  // last sample before the reference first moves to the first after it last moves.
  std::size_t window_begin = 0, window_end = 0;
  bool relative_reference = false;
  double windowStart() const { return reference.t[window_begin]; }
  double windowEnd() const { return reference.t[window_end - 1]; }
};

// The flight of `vehicle` in `log`, the run's time series as the commands that read a run folder
// read it (cli/run_folder.h: rows as run.json recorded them, times inside the scenario's
// max_time, increasing), and RUN_DIR/scenario.yaml for the reference's `relative`. `vehicle` may
// be empty when the run has one vehicle. Throws InputError for an unknown vehicle (naming the
// run's), a team run without `vehicle`, fewer than 2 samples, a position beyond
// kMaxFlightCoordinateM, or a reference that never moves (a hover: no window to compare, and no
// motion by which to place a log in time).
RunFlight runFlightOf(const RunLog& log, const std::filesystem::path& run_dir,
                      const std::string& vehicle);

}  // namespace cosim
