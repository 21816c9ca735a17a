#include "experiments/compare/flight_comparison.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/input_error.h"
#include "experiments/compare/comparison_warnings.h"
#include "experiments/compare/reference_alignment.h"

namespace cosim {

namespace {

std::string seconds(double a, double b) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.3f..%.3f s", a, b);
  return buf;
}

// The log on a clock counted from its first sample (times relative to `origin`), as the fit
// works on it: a log stamped in epoch seconds keeps its microseconds.
struct RebasedLog {
  double origin = 0.0;
  SampledPath position, reference;
};

// What compareFlights works with: the problem to fit and the log's pieces.
struct ComparisonSetting {
  const RunFlight* run = nullptr;
  const FlightLog* log = nullptr;
  RebasedLog rebased;
  AlignmentProblem problem;
};

double medianSpacing(const std::vector<double>& t) {
  std::vector<double> gaps;
  for (std::size_t i = 1; i < t.size(); ++i) gaps.push_back(t[i] - t[i - 1]);
  std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
  return gaps[gaps.size() / 2];
}

// Refuses a log that no time offset can place over the run's window.
void requireOverlap(const FlightComparison& c, const ComparisonSetting& st) {
  const SampledPath& path = st.log->hasReference() ? st.log->reference : st.log->position;
  const std::string log_span = seconds(path.start(), path.end());
  const std::string window = seconds(c.windowStart(), c.windowEnd());
  double lo, hi;
  offsetRange(st.problem, lo, hi);
  if (lo > hi)
    throw InputError(st.log->file, "",
                     "no overlap with the run: the log (" + log_span +
                         ") is shorter than the run's reference window (" + window + ")");
  if (searchedOffsets(st.problem).empty()) {
    char spacing[64];
    std::snprintf(spacing, sizeof spacing, "%.3g s", medianSpacing(path.t));
    throw InputError(st.log->file, "",
                     "no overlap with the run: wherever the run's reference window (" + window +
                         ") is placed in the log (" + log_span + "), it holds fewer than " +
                         std::to_string(kMinWindowLogSamples) +
                         " log samples (the log's samples are " + spacing +
                         " apart; are its times in seconds?)");
  }
}

// The given offset (rebased), or nothing if the log does not cover the window there.
std::optional<double> givenOffset(const ComparisonSetting& st, double offset) {
  double lo, hi;
  offsetRange(st.problem, lo, hi);
  const double tau = offset - st.rebased.origin;
  const double slack = 1e-9 + 4.0 * std::numeric_limits<double>::epsilon() * std::abs(offset);
  if (tau < lo - slack || tau > hi + slack) return std::nullopt;
  return std::clamp(tau, lo, hi);
}

// The real error at run sample k for the log at rebased offset tau and translation d.
double realError(const FlightComparison& c, const ComparisonSetting& st, std::size_t k, double tau,
                 const Eigen::Vector3d& d) {
  const double t_log = c.t[k] + tau;
  const Eigen::Vector3d p = st.rebased.position.at(t_log);
  return st.log->hasReference() ? (p - st.rebased.reference.at(t_log)).norm()
                                : (p - d - c.reference[k]).norm();
}

double rms(const std::vector<double>& e) {
  double sq = 0.0;
  for (const double v : e) sq += v * v;
  return std::sqrt(sq / static_cast<double>(e.size()));
}

// Every mode's alignment (the given offset instead of a fitted one, if there is one).
std::vector<std::pair<AlignMode, Alignment>> alignAllModes(const FlightComparison& c,
                                                           ComparisonSetting& st,
                                                           const ComparisonOptions& options,
                                                           const StopToken& stop) {
  std::vector<std::pair<AlignMode, Alignment>> out;
  for (const AlignMode m : allAlignModes()) {
    st.problem.translation = fittedTranslation(m);
    if (!fitsTime(m) || options.fixed_time_offset) {
      const std::optional<double> tau =
          givenOffset(st, options.fixed_time_offset ? options.time_offset : 0.0);
      if (tau) out.emplace_back(m, evaluateAlignment(st.problem, *tau));
      continue;
    }
    requireOverlap(c, st);
    out.emplace_back(m, fitAlignment(st.problem, stop));
  }
  return out;
}

AlignmentOutcome outcomeOf(const FlightComparison& c, const ComparisonSetting& st, AlignMode m,
                           const Alignment& a) {
  AlignmentOutcome o;
  o.mode = m;
  o.time_offset_s = st.rebased.origin + a.time_offset;
  o.translation_m = a.translation;
  std::vector<double> real(c.t.size());
  for (std::size_t k = 0; k < c.t.size(); ++k)
    real[k] = realError(c, st, k, a.time_offset, a.translation);
  o.real_rmse_m = rms(real);
  o.sim_rmse_m = c.sim_rmse_m;
  return o;
}

// The chosen alignment's errors, statistics and mean offset.
void errorsAndStatistics(FlightComparison& c, const ComparisonSetting& st, const Alignment& a) {
  Eigen::Vector3d offset_sum = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < c.t.size(); ++k) {
    const Eigen::Vector3d p = st.rebased.position.at(c.t[k] + a.time_offset);
    c.real.push_back(p - a.translation);
    offset_sum += p - c.sim[k];
    c.real_error.push_back(realError(c, st, k, a.time_offset, a.translation));
    c.real_max_error_m = std::max(c.real_max_error_m, c.real_error.back());
  }
  c.mean_offset_m = offset_sum / static_cast<double>(c.t.size());
  c.real_rmse_m = rms(c.real_error);
  const auto& lt = st.rebased.position.t;
  c.log_samples = static_cast<std::size_t>(
      std::upper_bound(lt.begin(), lt.end(), c.windowEnd() + a.time_offset) -
      std::lower_bound(lt.begin(), lt.end(), c.windowStart() + a.time_offset));
}

void simulatedErrors(FlightComparison& c) {
  for (std::size_t k = 0; k < c.t.size(); ++k) {
    c.sim_error.push_back((c.sim[k] - c.reference[k]).norm());
    c.sim_max_error_m = std::max(c.sim_max_error_m, c.sim_error.back());
  }
  c.sim_rmse_m = rms(c.sim_error);
}

ComparisonSetting settingFor(const FlightComparison& c, const RunFlight& run, const FlightLog& log,
                             const ComparisonOptions& options) {
  ComparisonSetting st;
  st.run = &run;
  st.log = &log;
  st.rebased.origin = log.position.start();
  st.rebased.position = log.position.shifted(st.rebased.origin);
  if (log.hasReference()) st.rebased.reference = log.reference.shifted(st.rebased.origin);
  st.problem.s = c.t;
  if (log.hasReference()) {
    st.problem.log = &st.rebased.reference;
    st.problem.target = c.reference;
  } else {
    st.problem.log = &st.rebased.position;
    st.problem.target = options.align_to == AlignTo::Flown ? c.sim : c.reference;
  }
  return st;
}

std::string targetInWords(const FlightLog& log, const ComparisonOptions& options) {
  if (log.hasReference()) return "the log's reference against the run's reference";
  return options.align_to == AlignTo::Flown ? "the log's positions against the simulated flight's"
                                            : "the log's positions against the run's reference";
}

// Refuses results that are not numbers (a ratio without a simulated error, an overflow).
void requireFiniteResults(const FlightComparison& c, const RunFlight& run, const FlightLog& log) {
  if (!(c.sim_rmse_m > 0.0) || !std::isfinite(c.sim_rmse_m))
    throw InputError(run.timeseries_file, "vehicle " + run.vehicle,
                     "the simulated flight's RMSE over the reference's window is " +
                         std::to_string(c.sim_rmse_m) + " m: no ratio real / simulated to give");
  if (!std::isfinite(c.real_rmse_m) || !c.mean_offset_m.allFinite() ||
      !std::isfinite(c.time_offset_s) || !c.start_offset_m.allFinite())
    throw InputError(log.file, "",
                     "the comparison's results are not finite numbers (positions or times too "
                     "large to square)");
}

}  // namespace

FlightComparison compareFlights(const RunFlight& run, const FlightLog& log,
                                const ComparisonOptions& options, const StopToken& stop) {
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
  simulatedErrors(c);
  c.alignment = options.align ? *options.align : defaultAlignMode(log.hasReference());
  c.alignment_target = targetInWords(log, options);
  c.real_against_log_reference = log.hasReference();
  ComparisonSetting st = settingFor(c, run, log, options);
  const auto aligned = alignAllModes(c, st, options, stop);
  const auto chosen = std::find_if(aligned.begin(), aligned.end(),
                                   [&](const auto& m) { return m.first == c.alignment; });
  if (chosen == aligned.end())  // only a given (or zero) offset can miss the log
    throw InputError(log.file, "",
                     "no overlap with the run: at time offset " +
                         std::to_string(options.fixed_time_offset ? options.time_offset : 0.0) +
                         " s the log (" + seconds(log.position.start(), log.position.end()) +
                         ") does not cover the run's reference window (" +
                         seconds(c.windowStart(), c.windowEnd()) + ")");
  for (const auto& [mode, a] : aligned) c.by_alignment.push_back(outcomeOf(c, st, mode, a));
  const Alignment& a = chosen->second;
  c.time_offset_fitted = fitsTime(c.alignment) && !options.fixed_time_offset;
  c.time_offset_s = st.rebased.origin + a.time_offset;
  c.start_offset_fitted = fittedTranslation(c.alignment) != FittedTranslation::None;
  c.start_offset_m = a.translation;
  c.alignment_rms_m = a.rms;
  errorsAndStatistics(c, st, a);
  if (c.log_samples < kMinFlightLogSamples)
    throw InputError(log.file, "",
                     "too few samples: " + std::to_string(c.log_samples) +
                         " inside the run's reference window (" +
                         seconds(c.windowStart(), c.windowEnd()) + " of run time), at least " +
                         std::to_string(kMinFlightLogSamples) + " needed");
  requireFiniteResults(c, run, log);
  c.real_axes = axisTracking(c.t, c.reference, st.rebased.position.shifted(a.time_offset), stop);
  c.sim_axes = axisTracking(c.t, c.reference, run.flown, stop);
  c.warnings = comparisonWarnings(c);
  return c;
}

}  // namespace cosim
