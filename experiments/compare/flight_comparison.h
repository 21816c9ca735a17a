#pragma once
// A real flight beside a simulated one: the log placed on the run's clock (and frame), then both
// flights' position errors against the run's reference over the reference's window.
//
// Alignment (experiments/compare/reference_alignment.h):
//   a log with a reference: its reference against the run's reference (the commanded paths are
//   the same file, so this places the log exactly, whatever the vehicles did);
//   a log without: its positions against the simulated vehicle's (AlignTo::Flown, the default)
//   or against the run's reference (AlignTo::Reference). Against the flown path a vehicle's lag
//   behind its reference stays in the real error as it stays in the simulated one; against the
//   reference the fit would absorb the real vehicle's lag into the offset and understate its
//   error.
//   The translation (start offset) is fitted when the run flew its reference relative to the
//   vehicle's start or the log has a reference (StartOffset::Auto), always (Fit) or never (None).
// Errors: a log with a reference, |position - its reference| at the aligned times; without one,
// |position - start offset - run reference|. The simulated error is |flown - run reference|.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "experiments/compare/flight_log.h"
#include "experiments/compare/run_flight.h"

namespace cosim {

enum class AlignTo { Flown, Reference };
enum class StartOffset { Auto, Fit, None };

struct ComparisonOptions {
  AlignTo align_to = AlignTo::Flown;
  StartOffset start_offset = StartOffset::Auto;
  bool fixed_time_offset = false;  // use time_offset instead of fitting it
  double time_offset = 0.0;
};

struct FlightComparison {
  double time_offset_s = 0.0;  // log time minus run time
  bool time_offset_fitted = true;
  Eigen::Vector3d start_offset_m = Eigen::Vector3d::Zero();  // log frame minus run frame
  bool start_offset_fitted = false;
  std::string alignment;  // what was matched to what, in words
  double alignment_rms_m = 0.0;
  // The run's samples in the reference's window, and both flights there (the real one in the
  // run's frame and on its clock).
  std::vector<double> t;
  std::vector<Eigen::Vector3d> reference, sim, real;
  std::vector<double> real_error, sim_error;
  double real_rmse_m = 0.0, sim_rmse_m = 0.0, real_max_error_m = 0.0, sim_max_error_m = 0.0;
  std::size_t log_samples = 0;  // log samples inside the aligned window
  double windowStart() const { return t.front(); }
  double windowEnd() const { return t.back(); }
};

// Throws InputError naming the log when it cannot cover the run's window (too short, or not at
// a fixed offset), or holds fewer than kMinFlightLogSamples samples inside it.
FlightComparison compareFlights(const RunFlight& run, const FlightLog& log,
                                const ComparisonOptions& options);

}  // namespace cosim
