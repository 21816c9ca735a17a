#pragma once
// Placing a flight log on a run's clock (and, optionally, in its frame) by least squares.
//
// The run gives target positions r_k at its times s_k (inside the reference's window); the log
// gives a path L(t) on its own clock. For a time offset tau (log time minus run time) and a
// translation d (log frame minus run frame), the misfit is
//     J(tau, d) = 1/N sum_k |L(s_k + tau) - d - r_k|^2,
// with L read by linear interpolation. For a given tau the best d is the mean of
// L(s_k + tau) - r_k (setting dJ/dd = 0) on the axes it is fitted on (x and y, or all three),
// zero on the others, which leaves J(tau) = mean|L - r|^2 - |d|^2; without a translation d = 0.
// J(tau) is minimised over every offset at which the log covers the whole window with at least
// kMinWindowLogSamples of its samples inside it (a log with far-apart samples around a flight is
// searched only where its samples are): a coarse scan (steps of kCoarseStep, or more for a long
// log: at most kMaxCoarseSteps in all, on at most kCoarseSamples of the s_k), then a
// golden-section search (Kiefer 1953) over the two steps around the best point, on all s_k, to
// kOffsetTolerance or to what the offsets' magnitude resolves (a bounded number of steps, so a
// log stamped in epoch seconds cannot keep it going). Callers pass logs whose times count from
// their first sample (SampledPath::shifted), so that a microsecond is resolvable.
#include <Eigen/Core>
#include <stdexcept>
#include <vector>

#include "core/stop_token.h"
#include "experiments/compare/sampled_path.h"

namespace cosim {

// Which components of the translation d are fitted.
enum class FittedTranslation { None, XY, XYZ };

struct AlignmentProblem {
  std::vector<double> s;                // run times, increasing
  std::vector<Eigen::Vector3d> target;  // r_k
  const SampledPath* log = nullptr;     // L
  FittedTranslation translation = FittedTranslation::None;
};

struct Alignment {
  double time_offset = 0.0;                               // tau, s
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // d, m
  double rms = 0.0;                                       // sqrt(J) at the optimum, m
};

// An interval [lo, hi] of time offsets.
struct OffsetInterval {
  double lo = 0.0, hi = 0.0;
};

// Thrown by fitAlignment when its stop token expires (an interrupt): nothing was placed.
struct AlignmentInterrupted : std::runtime_error {
  AlignmentInterrupted() : std::runtime_error("the fit was interrupted") {}
};

constexpr double kCoarseStep = 0.002;  // s
constexpr std::size_t kMaxCoarseSteps = 20000;
constexpr std::size_t kCoarseSamples = 400;
constexpr double kOffsetTolerance = 1e-6;  // s, the golden-section search's bracket at the end
// Log samples the window must hold at an offset the search considers (as compare-real needs).
constexpr std::size_t kMinWindowLogSamples = 10;

// The offsets at which the log covers [s.front(), s.back()]: [lo, hi]; lo > hi if none.
void offsetRange(const AlignmentProblem& problem, double& lo, double& hi);

// The offsets inside offsetRange at which at least kMinWindowLogSamples log samples fall in
// [s.front() + tau, s.back() + tau], as increasing disjoint intervals; empty if there are none.
std::vector<OffsetInterval> searchedOffsets(const AlignmentProblem& problem);

// J and d at a given offset.
Alignment evaluateAlignment(const AlignmentProblem& problem, double time_offset);

// The least-squares offset (and translation). Requires searchedOffsets to be non-empty
// (std::invalid_argument otherwise); throws AlignmentInterrupted when `stop` expires.
Alignment fitAlignment(const AlignmentProblem& problem,
                       const StopToken& stop = StopToken::untimed());

}  // namespace cosim
