#pragma once
// One vehicle's flight in a run folder written by `cosim run`, as compare-real needs it: its
// reference and flown positions at the control rate (timeseries.csv), the window the reference
// covers, and whether the scenario flew it relative to the vehicle's start
// (vehicles[i].reference.relative in the run's scenario.yaml).
#include <filesystem>
#include <string>

#include "experiments/compare/sampled_path.h"

namespace cosim {

struct RunFlight {
  std::string vehicle;
  std::string timeseries_file;  // named in errors about the run's samples
  SampledPath reference, flown;  // on the same times
  // The reference's duration as samples [window_begin, window_end) of the time series: from the
  // last sample before the reference first moves to the first after it last moves (all samples
  // if it never moves, e.g. a hover).
  std::size_t window_begin = 0, window_end = 0;
  bool relative_reference = false;
  double windowStart() const { return reference.t[window_begin]; }
  double windowEnd() const { return reference.t[window_end - 1]; }
};

// Reads RUN_DIR/timeseries.csv and RUN_DIR/scenario.yaml. `vehicle` may be empty when the run
// has one vehicle. Throws InputError for missing or malformed files, an unknown vehicle (naming
// the run's), or a team run without `vehicle`.
RunFlight readRunFlight(const std::filesystem::path& run_dir, const std::string& vehicle);

}  // namespace cosim
