#include "experiments/compare/flight_comparison.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/input_error.h"
#include "experiments/compare/reference_alignment.h"

namespace cosim {

namespace {

std::string seconds(double a, double b) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.3f..%.3f s", a, b);
  return buf;
}

Alignment alignLog(const FlightComparison& c, const FlightLog& log, const AlignmentProblem& pr,
                   const ComparisonOptions& options) {
  double lo, hi;
  offsetRange(pr, lo, hi);
  const SampledPath& path = *pr.log;
  const std::string log_span = seconds(path.start(), path.end());
  const std::string window = seconds(c.windowStart(), c.windowEnd());
  if (options.fixed_time_offset) {
    if (options.time_offset < lo - 1e-9 || options.time_offset > hi + 1e-9)
      throw InputError(log.file, "",
                       "no overlap with the run: at time offset " +
                           std::to_string(options.time_offset) + " s the log (" + log_span +
                           ") does not cover the run's reference window (" + window + ")");
    return evaluateAlignment(pr, options.time_offset);
  }
  if (lo > hi)
    throw InputError(log.file, "",
                     "no overlap with the run: the log (" + log_span +
                         ") is shorter than the run's reference window (" + window + ")");
  return fitAlignment(pr);
}

void errorsAndStatistics(FlightComparison& c, const FlightLog& log) {
  double real_sq = 0.0, sim_sq = 0.0;
  for (std::size_t k = 0; k < c.t.size(); ++k) {
    const double t_log = c.t[k] + c.time_offset_s;
    const Eigen::Vector3d p = log.position.at(t_log);
    c.real.push_back(p - c.start_offset_m);
    const double e_real = log.hasReference() ? (p - log.reference.at(t_log)).norm()
                                             : (c.real.back() - c.reference[k]).norm();
    const double e_sim = (c.sim[k] - c.reference[k]).norm();
    c.real_error.push_back(e_real);
    c.sim_error.push_back(e_sim);
    real_sq += e_real * e_real;
    sim_sq += e_sim * e_sim;
    c.real_max_error_m = std::max(c.real_max_error_m, e_real);
    c.sim_max_error_m = std::max(c.sim_max_error_m, e_sim);
  }
  c.real_rmse_m = std::sqrt(real_sq / c.t.size());
  c.sim_rmse_m = std::sqrt(sim_sq / c.t.size());
  const auto& lt = log.position.t;
  c.log_samples = static_cast<std::size_t>(
      std::upper_bound(lt.begin(), lt.end(), c.windowEnd() + c.time_offset_s) -
      std::lower_bound(lt.begin(), lt.end(), c.windowStart() + c.time_offset_s));
}

}  // namespace

FlightComparison compareFlights(const RunFlight& run, const FlightLog& log,
                                const ComparisonOptions& options) {
  FlightComparison c;
  for (std::size_t k = run.window_begin; k < run.window_end; ++k) {
    c.t.push_back(run.reference.t[k]);
    c.reference.push_back(run.reference.p[k]);
    c.sim.push_back(run.flown.p[k]);
  }
  if (c.t.size() < kMinFlightLogSamples)
    throw InputError(run.timeseries_file, "vehicle " + run.vehicle,
                     "the reference's window holds " + std::to_string(c.t.size()) +
                         " samples, too few to compare");
  AlignmentProblem pr;
  pr.s = c.t;
  // A log with a reference is placed by it, and two references of one file differ in time and,
  // at most, in frame: the frame is fitted too (unless told not to), or a frame offset would
  // pull the time offset. It does not enter the real error (position minus its own reference).
  c.start_offset_fitted =
      options.start_offset == StartOffset::Fit ||
      (options.start_offset == StartOffset::Auto && (run.relative_reference || log.hasReference()));
  pr.fit_translation = c.start_offset_fitted;
  if (log.hasReference()) {
    pr.log = &log.reference;
    pr.target = c.reference;
    c.alignment = "the log's reference against the run's reference";
  } else if (options.align_to == AlignTo::Flown) {
    pr.log = &log.position;
    pr.target = c.sim;
    c.alignment = "the log's positions against the simulated flight's";
  } else {
    pr.log = &log.position;
    pr.target = c.reference;
    c.alignment = "the log's positions against the run's reference";
  }
  const Alignment a = alignLog(c, log, pr, options);
  c.time_offset_fitted = !options.fixed_time_offset;
  c.time_offset_s = a.time_offset;
  c.start_offset_m = a.translation;
  c.alignment_rms_m = a.rms;
  errorsAndStatistics(c, log);
  if (c.log_samples < kMinFlightLogSamples)
    throw InputError(log.file, "",
                     "too few samples: " + std::to_string(c.log_samples) +
                         " inside the run's reference window (" +
                         seconds(c.windowStart(), c.windowEnd()) + " of run time), at least " +
                         std::to_string(kMinFlightLogSamples) + " needed");
  return c;
}

}  // namespace cosim
