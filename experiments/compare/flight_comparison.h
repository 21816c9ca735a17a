#pragma once
// A real flight beside a simulated one: the log placed on the run's clock (and frame), then both
// flights' position errors against the run's reference over the reference's window.
//
// Alignment (experiments/compare/reference_alignment.h), of what is matched to what:
//   a log with a reference: its reference against the run's reference (the commanded paths are
//   the same file, so this places the log exactly, whatever the vehicles did);
//   a log without: its positions against the simulated vehicle's (AlignTo::Flown, the default)
//   or against the run's reference (AlignTo::Reference). Against the flown path a vehicle's lag
//   behind its reference stays in the real error as it stays in the simulated one; against the
//   reference the fit would absorb the real vehicle's lag into the offset and understate its
//   error.
// What is fitted is the AlignMode (alignment_mode.h): nothing, the time offset, and the
// translation in x,y or x,y,z. Every mode is evaluated (rmse_by_alignment), the chosen one gives
// the result, and the mean offset of the real flight from the simulated one after the time
// alignment is reported whether or not it was fitted away.
// Errors: a log with a reference, |position - its reference| at the aligned times; without one,
// |position - start offset - run reference|. The simulated error is |flown - run reference|.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/stop_token.h"
#include "experiments/compare/alignment_mode.h"
#include "experiments/compare/axis_tracking.h"
#include "experiments/compare/flight_log.h"
#include "experiments/compare/run_flight.h"

namespace cosim {

enum class AlignTo { Flown, Reference };

// Above these a fitted time shift or a mean offset is warned of (docs/compare_real.md): at the
// figure-eight's 1.2 m/s peak speed 50 ms is 6 cm of path, and 2 cm is about the simulated
// Crazyflie's whole tracking RMSE on it, so either is the size of the errors being compared.
constexpr double kLargeTimeShiftS = 0.05;
constexpr double kLargeOffsetM = 0.02;

struct ComparisonOptions {
  AlignTo align_to = AlignTo::Flown;
  std::optional<AlignMode> align;  // none: defaultAlignMode
  bool fixed_time_offset = false;  // use time_offset instead of fitting it
  double time_offset = 0.0;
};

// The result at one alignment mode.
struct AlignmentOutcome {
  AlignMode mode = AlignMode::None;
  double time_offset_s = 0.0;
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();
  double real_rmse_m = 0.0, sim_rmse_m = 0.0;
};

struct FlightComparison {
  AlignMode alignment = AlignMode::Time;  // the mode used
  double time_offset_s = 0.0;             // log time minus run time
  bool time_offset_fitted = true;
  Eigen::Vector3d start_offset_m = Eigen::Vector3d::Zero();  // fitted translation, log minus run
  bool start_offset_fitted = false;
  // Mean of real minus simulated position over the window after the time alignment (log frame).
  Eigen::Vector3d mean_offset_m = Eigen::Vector3d::Zero();
  std::string alignment_target;             // what was matched to what, in words
  bool real_against_log_reference = false;  // the real error is against the log's own reference
  double alignment_rms_m = 0.0;
  std::vector<AlignmentOutcome> by_alignment;  // every mode the log covers, in allAlignModes order
  AxisTracking real_axes, sim_axes;            // against the run's reference
  std::vector<std::string> warnings;
  // The run's samples in the reference's window, and both flights there (the real one in the
  // run's frame and on its clock).
  std::vector<double> t;
  std::vector<Eigen::Vector3d> reference, sim, real;
  std::vector<double> real_error, sim_error;
  double real_rmse_m = 0.0, sim_rmse_m = 0.0, real_max_error_m = 0.0, sim_max_error_m = 0.0;
  std::size_t log_samples = 0;  // log samples inside the aligned window
  double windowStart() const { return t.front(); }
  double windowEnd() const { return t.back(); }
  double ratio() const { return real_rmse_m / sim_rmse_m; }
};

// Throws InputError naming the log when it cannot cover the run's window (too short, no offset
// at which the window holds enough of its samples, or not at the given offset), or holds fewer
// than kMinFlightLogSamples samples inside it; naming the run when the simulated RMSE is zero
// (no ratio). Throws AlignmentInterrupted when `stop` expires.
FlightComparison compareFlights(const RunFlight& run, const FlightLog& log,
                                const ComparisonOptions& options,
                                const StopToken& stop = StopToken::untimed());

}  // namespace cosim
